#pragma once
// GJK distance between two convex sets given only by support mappings (Gilbert, Johnson &
// Keerthi 1988; van den Bergen 1999 termination tests). Generic over any type with
//   Vec3 support(const Vec3& d) const   // farthest point along d, world frame
// so one algorithm serves every convex part.
//
//   GjkResult gjk_distance(a, b, GjkOptions{warm_direction, margin, scale})
// Returns the closest points and the distance, or `intersecting` when the sets overlap
// (then `simplex` seeds EPA), or `beyond_margin` as soon as a separating direction proves
// the distance exceeds options.margin (a cheap "no contact" exit for the crust method).
// Warm start: pass last step's separation vector (point_a - point_b) as warm_direction; or, better,
// last step's simplex re-posed (points of A - B) as warm_simplex: a persistent contact then
// usually needs one iteration.
#include <cmath>
#include <limits>

#include "talus/collide/gjk_simplex.h"

namespace talus {

struct GjkOptions {
  Vec3 warm_direction;  ///< initial guess of point_a - point_b; zero: use centres or +x
  const Simplex* warm_simplex = nullptr;  ///< points of A - B to start from (replaces warm_direction)
  double margin = std::numeric_limits<double>::infinity();  ///< exit once distance > margin (m)
  double scale = 1;          ///< size of the shapes (m); sets the absolute tolerances
  double tolerance = 1e-10;  ///< distance accuracy relative to scale
  int max_iterations = 64;
};

struct GjkResult {
  double distance = 0;   ///< between the sets, 0 if intersecting (m)
  Vec3 point_a;          ///< closest point on A (m)
  Vec3 point_b;          ///< closest point on B (m)
  Vec3 separation;       ///< point_a - point_b; the warm start for next step (m)
  bool intersecting = false;
  bool beyond_margin = false;
  int iterations = 0;
  Simplex simplex;       ///< final simplex (EPA seed when intersecting)
};

// Supports that name their corner (OrientedBoxSupport) give it to the point, for the simplex's code.
template <class SupportA, class SupportB>
inline SupportPoint minkowski_support(const SupportA& a, const SupportB& b, const Vec3& d) {
  if constexpr (requires(std::uint32_t* id) {
                  a.support(d, id);
                  b.support(d, id);
                }) {
    std::uint32_t corner_a, corner_b;
    const Vec3 pa = a.support(d, &corner_a), pb = b.support(-d, &corner_b);
    return {pa - pb, pa, pb, corner_a | corner_b << 3};
  } else {
    const Vec3 pa = a.support(d), pb = b.support(-d);
    return {pa - pb, pa, pb};
  }
}

// Shrinks s to its part nearest the origin (*closest); true, with r marked intersecting, when the
// origin is inside it or within eps of it.
inline bool origin_enclosed(Simplex& s, double eps, GjkResult& r, Vec3* closest) {
  bool inside = false;
  *closest = reduce_simplex(s, &inside);
  if (!inside && norm(*closest) > eps) return false;
  r.intersecting = true;
  r.separation = *closest;
  return true;
}

template <class SupportA, class SupportB>
GjkResult gjk_distance(const SupportA& a, const SupportB& b, const GjkOptions& opt) {
  GjkResult r;
  const double eps = opt.tolerance * opt.scale;  // absolute distance tolerance
  Vec3 v = opt.warm_direction;
  if (!(norm2(v) > 0)) v = Vec3{1, 0, 0};
  Simplex& s = r.simplex;
  double prev2 = std::numeric_limits<double>::infinity();
  if (opt.warm_simplex && opt.warm_simplex->size > 0) {
    s.assign(*opt.warm_simplex);
    Vec3 nv;
    if (origin_enclosed(s, eps, r, &nv)) return r;
    v = nv;
    prev2 = norm2(nv);
  }
  for (r.iterations = 1; r.iterations <= opt.max_iterations; ++r.iterations) {
    const SupportPoint p = minkowski_support(a, b, -v);
    const double v2 = norm2(v), vw = dot(v, p.w);
    // vw / |v| is a lower bound on the distance for any v.
    if (vw > 0 && vw * vw > opt.margin * opt.margin * v2) {
      r.beyond_margin = true;
      r.distance = vw / std::sqrt(v2);
      return r;
    }
    if (s.size > 0) {
      if (v2 - vw <= eps * std::sqrt(v2)) break;  // upper minus lower bound below tolerance
      bool repeated = false;
      for (int k = 0; k < s.size; ++k) repeated = repeated || norm2(s.p[k].w - p.w) <= eps * eps;
      if (repeated) break;
    }
    Simplex before;
    before.assign(s);
    s.push(p);
    Vec3 nv;
    if (origin_enclosed(s, eps, r, &nv)) return r;
    if (norm2(nv) >= prev2) {  // no progress: rounding noise; keep the previous simplex
      s.assign(before);
      break;
    }
    prev2 = norm2(nv);
    v = nv;
  }
  r.point_a = r.point_b = Vec3{};
  for (int k = 0; k < s.size; ++k) {
    r.point_a += s.p[k].a * s.lambda[k];
    r.point_b += s.p[k].b * s.lambda[k];
  }
  r.separation = r.point_a - r.point_b;
  r.distance = norm(r.separation);
  return r;
}

}  // namespace talus
