#pragma once
// Every rigid body's parts placed in the world once per step (pose, box axes, culling capsule),
// so that each body pair reads them instead of turning both quaternions into matrices again for
// every neighbour: a cross has some 17 candidate neighbours in a pile, and placing its two
// arms was most of what a candidate pair cost.
//
// It also keeps each body's travel: a bound on how far any point of the body has moved since
// the neighbour list was built, so that a pair found apart by a gap g need not be looked at
// again until the two travels have grown by g (conservative advancement; a static pile's
// neighbours, and most of a flowing one's, are then skipped for hundreds of steps).
#include <cstdint>
#include <vector>

#include "talus/body/particles.h"
#include "talus/collide/oriented_box.h"
#include "talus/shape/composite_shape.h"

namespace talus {

// A convex part placed in the world: three cache lines, the first holding all the capsule cull
// reads (axis, radius, centre), so a pair whose capsules are apart touches one line per part.
struct alignas(64) PlacedPart {
  Vec3 capsule_axis;          ///< world half-axis of the culling capsule (m)
  double capsule_radius = 0;  ///< m
  bool is_box = false;
  OrientedBox box;            ///< centre and axes always set; half extents too when the part is a box
  Quat orientation;           ///< part to world

  Pose pose() const { return {box.centre, orientation}; }
};

// A body's frame in the world, and the centre of its part-bounding box.
struct BodyFrame {
  Vec3 axis[3];     ///< body axes in the world (columns of the rotation matrix)
  Vec3 box_centre;  ///< world centre of the composite's box (CompositeShape::box_centre)
};

void place_part(const CompositePart& part, const Pose& body, PlacedPart& out);

class PlacedBodies {
 public:
  // Places every particle of `p` (ghosts included) whose shape is not the sphere (index 0).
  // Every particle's travel grows by the motion since the last call.
  void place(const ParticleStore& p, const std::vector<CompositeShape>& shapes);
  // The travels restart from zero at the next place() (the list was rebuilt: new indices).
  void restart_travel() { restart_travel_ = true; }
  // The farthest any point of body i can have moved since the travels restarted (m): the sum
  // over steps of |dx| + 2 R sin(theta / 2), the chord of a turn by theta at the bounding radius R.
  double travel(std::size_t i) const { return travel_[i]; }
  const BodyFrame& body(std::size_t i) const { return bodies_[i]; }
  const PlacedPart* parts(std::size_t i) const { return parts_.data() + offset_[i]; }
  std::size_t part_count(std::size_t i) const { return offset_[i + 1] - offset_[i]; }

 private:
  std::vector<BodyFrame> bodies_;
  std::vector<std::uint32_t> offset_;  ///< first part of each particle in parts_
  std::vector<PlacedPart> parts_;
  std::vector<Vec3> last_position_;
  std::vector<Quat> last_orientation_;
  std::vector<double> travel_;
  bool restart_travel_ = true;
};

}  // namespace talus
