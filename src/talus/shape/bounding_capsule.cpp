#include "talus/shape/bounding_capsule.h"

#include <algorithm>
#include <cmath>
#include <variant>

#include "talus/shape/convex_shape.h"

namespace talus {

BoundingCapsule bounding_capsule(const ConvexShape& shape) {
  if (const Box* b = std::get_if<Box>(&shape.geometry)) {
    // Corners (+-h_k, +-h_1, +-h_2) lie at distance |(h_1, h_2)| from the long axis segment.
    const Vec3 h = b->half_extents;
    const int k = h.x >= h.y && h.x >= h.z ? 0 : (h.y >= h.z ? 1 : 2);
    Vec3 axis;
    axis[k] = h[k];
    const double r = std::sqrt(norm2(h) - h[k] * h[k]);
    return {axis, r};
  }
  if (const Cylinder* c = std::get_if<Cylinder>(&shape.geometry)) return {{0, 0, c->half_height}, c->radius};
  return {{}, shape.bounding_radius};
}

}  // namespace talus
