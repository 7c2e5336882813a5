#pragma once
// CompositeShape: a rigid body made of convex parts, each placed by a pose in the body frame.
// Parts may overlap (mass_properties counts shared volume once). The narrow phase works per
// pair of parts; the body-level bounding radius is for the broad phase.
// make_huet_cross(): the cross particle of Huet et al. (2021) Sec. III B — two cuboids
// Lp x Wp x Hp = 27 x 2 x 3 mm crossing at their centres, arms along x and y, thickness along z.
#include <vector>

#include "talus/shape/bounding_capsule.h"
#include "talus/shape/convex_shape.h"
#include "talus/shape/pose.h"

namespace talus {

struct CompositePart {
  ConvexShape shape;
  Pose pose;  ///< part frame in the body frame
  BoundingCapsule capsule;  ///< in the part frame: culls part pairs before the narrow phase
};

struct CompositeShape {
  std::vector<CompositePart> parts;
  double bounding_radius = 0;  ///< about the body origin, covers every part (m)
  // Box about every part, aligned with the body axes: a body-level separating-axis cull. For the
  // flat Huet cross it is 27 x 27 x 3 mm, and its thickness axis parts most neighbours.
  Vec3 box_centre;  ///< body frame (m)
  Vec3 box_half;    ///< half extents (m)

  void add(ConvexShape shape, const Pose& pose);
};

// Arm length, arm width and thickness in metres; crust as in make_box (applies to both arms).
CompositeShape make_huet_cross(double length = 27e-3, double width = 2e-3, double height = 3e-3,
                               double crust = 0);

}  // namespace talus
