#pragma once
// The smallest capsule about a convex shape's local origin that a part-pair cull needs: a
// segment [-half_axis, +half_axis] swept by a ball of `radius`. Far tighter than the bounding
// sphere for the long thin arms of the Huet et al. 2021 cross (27 x 2 x 3 mm: radius 1.8 mm
// instead of 13.6 mm), whose two arms share one centre, so their bounding spheres never cull.
//   bounding_capsule(geometry) : box -> segment along its longest side, radius = half-diagonal
//                                of the cross-section; cylinder -> its axis; otherwise a ball.
//   segment_distance2(...)      : squared distance of two world capsule segments.
//   capsules_apart(...)         : true when two world capsules cannot touch.
#include <algorithm>

#include "talus/math/vec3.h"

namespace talus {

struct ConvexShape;

struct BoundingCapsule {
  Vec3 half_axis;     ///< half the segment, shape frame (m)
  double radius = 0;  ///< (m)
};

BoundingCapsule bounding_capsule(const ConvexShape& shape);

// Squared distance of the segments ca + s ua and cb + t ub, s, t in [-1, 1] (Ericson,
// Real-Time Collision Detection, Sec. 5.1.9, closest points of segments). Inline: the pair loop
// of rigid bodies runs it for every pair of parts.
inline double segment_distance2(const Vec3& ca, const Vec3& ua, const Vec3& cb, const Vec3& ub) {
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
  return norm2(r + ua * s - ub * t);
}

// Capsules centred at ca and cb with world half-axes ua, ub: true if they cannot touch.
inline bool capsules_apart(const Vec3& ca, const Vec3& ua, double ra, const Vec3& cb, const Vec3& ub, double rb) {
  const double reach = ra + rb;
  return segment_distance2(ca, ua, cb, ub) >= reach * reach;
}

}  // namespace talus
