#pragma once
// Every rigid body's parts placed in the world once per step (pose, box axes, culling capsule),
// so that each body pair reads them instead of turning both quaternions into matrices again for
// every neighbour: a cross has some 17 candidate neighbours in a pile, and placing its two
// arms was most of what a candidate pair cost.
#include <cstdint>
#include <vector>

#include "talus/body/particles.h"
#include "talus/collide/oriented_box.h"
#include "talus/shape/composite_shape.h"

namespace talus {

// A convex part placed in the world.
struct PlacedPart {
  Pose pose;
  OrientedBox box;      ///< axes always set; centre and half extents too when the part is a box
  Vec3 capsule_axis;    ///< world half-axis of the culling capsule (m)
  double capsule_radius = 0;
  bool is_box = false;
};

// A body's frame in the world, and the centre of its part-bounding box.
struct BodyFrame {
  Vec3 axis[3];     ///< body axes in the world (columns of the rotation matrix)
  Vec3 box_centre;  ///< world centre of the composite's box (CompositeShape::box_centre)
};

PlacedPart place_part(const CompositePart& part, const Pose& body);

class PlacedBodies {
 public:
  // Places every particle of `p` (ghosts included) whose shape is not the sphere (index 0).
  void place(const ParticleStore& p, const std::vector<CompositeShape>& shapes);
  const BodyFrame& body(std::size_t i) const { return bodies_[i]; }
  const PlacedPart* parts(std::size_t i) const { return parts_.data() + offset_[i]; }

 private:
  std::vector<BodyFrame> bodies_;
  std::vector<std::uint32_t> offset_;  ///< first part of each particle in parts_
  std::vector<PlacedPart> parts_;
};

}  // namespace talus
