#include "talus/scenario/rigid_body_type.h"

#include "talus/shape/mass_properties.h"

namespace talus {

RigidBodyType make_rigid_body_type(const CompositeShape& shape, double density) {
  const MassProperties mp = mass_properties(shape, density);
  RigidBodyType t;
  t.shape = to_principal_frame(shape, mp);
  t.volume = mp.volume;
  t.mass = mp.mass;
  t.inertia = mp.principal_moments;
  t.radius = t.shape.bounding_radius;
  t.principal = mp.principal_pose();
  return t;
}

ParticleInit rigid_particle(const RigidBodyType& type, int shape_index, const Vec3& position, const Quat& orientation,
                            int species) {
  ParticleInit p;
  // The World steps the principal frame: a user's orientation means the shape as given.
  p.position = position + orientation.rotate(type.principal.position);
  p.orientation = orientation * type.principal.orientation;
  p.radius = type.radius;
  p.mass = type.mass;
  p.inertia = type.inertia;
  p.species = species;
  p.shape = shape_index;
  return p;
}

}  // namespace talus
