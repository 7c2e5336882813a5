#pragma once
// What a particle looks like from outside: a few convex parts (oriented boxes, spheres) that
// the collapse image analyses rasterise. The engine builds them from its shapes, so the image
// code needs no shape table and works alike on spheres, crosses and anything made of boxes.
#include <vector>

#include "talus/analysis/snapshot.h"

namespace talus::collapse {

struct FootprintBox {
  Vec3 centre;         ///< m, centre of the box (world frame, or body frame in a template)
  Vec3 half_extents;   ///< m, half side lengths along the box's own axes
  Quat orientation;    ///< rotation from the box's axes to the frame of `centre`
};

struct FootprintSphere {
  Vec3 centre;         ///< m, centre (world frame, or body frame in a template)
  double radius = 0;   ///< m
};

// The convex parts of one particle. A Footprint in world coordinates is what the images read;
// the same type in the particle's body frame (origin at its centre of mass) is a template.
struct Footprint {
  std::vector<FootprintBox> boxes;
  std::vector<FootprintSphere> spheres;
};

// Moves a body-frame template to a pose (position of the centre of mass, body-to-world rotation).
Footprint place_footprint(const Footprint& body_frame, const Vec3& position, const Quat& orientation);

// One world footprint per particle of the snapshot, index-aligned with Snapshot::particles:
// shapes[p.shape] placed at each particle's pose. Fixed particles get an empty footprint
// (they are walls or bases, not part of the pile). Throws std::out_of_range on an unknown shape.
std::vector<Footprint> place_footprints(const Snapshot& snapshot, const std::vector<Footprint>& shapes);

// Fallback when no shape is known: each mobile particle as a sphere of its bounding radius.
// It overestimates the extent of elongated particles by up to their bounding radius.
std::vector<Footprint> bounding_sphere_footprints(const Snapshot& snapshot);

}  // namespace talus::collapse
