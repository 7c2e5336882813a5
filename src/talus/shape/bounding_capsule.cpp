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

bool capsules_apart(const Vec3& ca, const Vec3& ua, double ra, const Vec3& cb, const Vec3& ub, double rb) {
  // Segments ca + s ua and cb + t ub, s, t in [-1, 1]; minimise |r + s ua - t ub|, r = ca - cb.
  const Vec3 r = ca - cb;
  const double a = norm2(ua), e = norm2(ub), b = dot(ua, ub), c = dot(ua, r), f = dot(ub, r);
  const double denom = a * e - b * b;
  double s = 0, t = 0;
  if (a > 0 && e > 0) {
    s = denom > 1e-12 * a * e ? std::clamp((b * f - c * e) / denom, -1.0, 1.0) : 0.0;
    t = (b * s + f) / e;
    if (t < -1 || t > 1) {
      t = std::clamp(t, -1.0, 1.0);
      s = std::clamp((b * t - c) / a, -1.0, 1.0);
    }
  } else if (a > 0) {
    s = std::clamp(-c / a, -1.0, 1.0);
  } else if (e > 0) {
    t = std::clamp(f / e, -1.0, 1.0);
  }
  const double reach = ra + rb;
  return norm2(r + ua * s - ub * t) >= reach * reach;
}

}  // namespace talus
