#pragma once
// A rigid body kind ready for the World: its shape moved to the principal frame, with the
// mass, principal moments and bounding radius from geometry.
#include "talus/shape/composite_shape.h"
#include "talus/world/world.h"

namespace talus {

struct RigidBodyType {
  CompositeShape shape;  ///< parts in the principal frame, centre of mass at the origin
  double volume = 0;     ///< m^3, overlaps of parts counted once
  double mass = 0;       ///< kg
  Vec3 inertia;          ///< kg m^2, principal moments
  double radius = 0;     ///< m, bounding radius about the centre of mass
  Pose principal;        ///< the principal frame (centre of mass, axes) in the frame the shape was given in
};

RigidBodyType make_rigid_body_type(const CompositeShape& shape, double density);

// A particle of that kind whose shape frame (the one its parts were given in) lies at `position`
// and `orientation`, with the given shape index in the World.
ParticleInit rigid_particle(const RigidBodyType& type, int shape_index, const Vec3& position, const Quat& orientation,
                            int species);

}  // namespace talus
