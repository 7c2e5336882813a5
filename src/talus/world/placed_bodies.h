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

// A convex part placed in the world: two cache lines, written every step, so the parts of a
// 2000-part pile fit in half a core's L2. What does not move (capsule radius and half axis,
// whether the part is a box) is read from the CompositePart; the part's orientation, needed only
// by the general narrow phase and the wall contacts, is the body's times the part's.
struct alignas(64) PlacedPart {
  OrientedBox box;  ///< centre and axes always set; half extents too when the part is a box
  bool is_box = false;
};
static_assert(sizeof(PlacedPart) == 128);

// The world half-axis of a placed part's culling capsule (m).
inline Vec3 capsule_axis(const PlacedPart& placed, const CompositePart& part) {
  const Vec3 c = part.capsule.half_axis;
  return placed.box.axis[0] * c.x + placed.box.axis[1] * c.y + placed.box.axis[2] * c.z;
}

// The pose of a placed part, whose body has orientation `body`.
inline Pose part_pose(const PlacedPart& placed, const CompositePart& part, const Quat& body) {
  return {placed.box.centre, body * part.pose.orientation};
}

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
  const double* travels() const { return travel_.data(); }
  // The sum over steps of the largest step travel of any body (ghosts included), since the
  // travels restarted: no body's travel grows by more than this does, so a pass can tell that a
  // whole row of pairs stays apart without reading its neighbours' travels.
  double travel_clock() const { return travel_clock_; }
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
  double travel_clock_ = 0;
  bool restart_travel_ = true;
};

}  // namespace talus
