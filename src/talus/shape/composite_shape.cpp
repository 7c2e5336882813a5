#include "talus/shape/composite_shape.h"

#include <algorithm>
#include <numbers>

namespace talus {

void CompositeShape::add(ConvexShape shape, const Pose& pose) {
  bounding_radius = std::max(bounding_radius, norm(pose.position) + shape.bounding_radius);
  const Aabb part = aabb(shape.geometry, pose);  // nominal shape: holds the crust-rounded one
  Vec3 lo = part.lo, hi = part.hi;
  if (!parts.empty())
    for (int k = 0; k < 3; ++k)
      lo[k] = std::min(lo[k], box_centre[k] - box_half[k]), hi[k] = std::max(hi[k], box_centre[k] + box_half[k]);
  box_centre = (lo + hi) * 0.5;
  box_half = (hi - lo) * 0.5;
  const BoundingCapsule capsule = bounding_capsule(shape);
  parts.push_back({std::move(shape), pose, capsule});
}

CompositeShape make_huet_cross(double length, double width, double height, double crust) {
  // Huet et al. 2021, Sec. III B: Lp = 27 mm, Wp = 2 mm, Hp = 3 mm.
  const ConvexShape arm = make_box({0.5 * length, 0.5 * width, 0.5 * height}, crust);
  CompositeShape cross;
  cross.add(arm, Pose{});
  cross.add(arm, Pose{{}, Quat::from_axis_angle({0, 0, 1}, 0.5 * std::numbers::pi)});
  return cross;
}

}  // namespace talus
