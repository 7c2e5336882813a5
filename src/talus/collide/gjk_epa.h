#pragma once
// EPA (expanding polytope, van den Bergen 2001): penetration depth of two intersecting convex
// sets, seeded by the simplex GJK ends with. The crust method only needs it as a fallback when
// the cores themselves intersect (overlap beyond the crust).
//   EpaResult epa_penetration(a, b, gjk_simplex, scale)
// normal is the outward normal of A - B at its boundary point closest to the origin: moving A
// by -depth * normal separates the sets. ok == false when the difference is flat (zero volume)
// or the polytope broke down; the caller then needs its own fallback.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "talus/collide/gjk.h"

namespace talus {

struct EpaResult {
  bool ok = false;
  double depth = 0;  ///< (m)
  Vec3 normal;       ///< unit, outward of A - B
  Vec3 point_a;      ///< deepest point of A inside B (m)
  Vec3 point_b;      ///< deepest point of B inside A (m)
  int iterations = 0;
};

namespace epa_detail {
struct Face {
  int v[3];
  Vec3 n;
  double d;
  bool alive;
};
inline bool make_face(const std::vector<SupportPoint>& p, int a, int b, int c, Face* f) {
  const Vec3 n = cross(p[b].w - p[a].w, p[c].w - p[a].w);
  const double len = norm(n);
  if (!(len > 0)) return false;
  *f = {{a, b, c}, n / len, dot(n, p[a].w) / len, true};
  return true;
}
}  // namespace epa_detail

template <class SupportA, class SupportB>
EpaResult epa_penetration(const SupportA& a, const SupportB& b, const Simplex& seed, double scale,
                          double tolerance = 1e-9, int max_iterations = 128) {
  using epa_detail::Face;
  EpaResult r;
  const double eps = tolerance * scale;
  std::vector<SupportPoint> pts(seed.p.data(), seed.p.data() + seed.size);

  // Grow the seed into a tetrahedron with supports away from its affine hull.
  static const Vec3 kAxes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  auto distance_to_hull = [&](const Vec3& w) {
    if (pts.size() == 1) return norm(w - pts[0].w);
    if (pts.size() == 2) return norm(cross(w - pts[0].w, normalized_or_zero(pts[1].w - pts[0].w)));
    return std::abs(dot(w - pts[0].w, normalized_or_zero(cross(pts[1].w - pts[0].w, pts[2].w - pts[0].w))));
  };
  while (pts.size() < 4) {
    std::vector<Vec3> dirs(kAxes, kAxes + 6);
    if (pts.size() == 2) {
      const Vec3 e = pts[1].w - pts[0].w;
      const Vec3 u = normalized_or_zero(cross(e, std::abs(e.x) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0}));
      const Vec3 t = normalized_or_zero(cross(e, u));
      dirs = {u, -u, t, -t, (u + t) * 0.7071, -(u + t) * 0.7071};
    } else if (pts.size() == 3) {
      const Vec3 n = normalized_or_zero(cross(pts[1].w - pts[0].w, pts[2].w - pts[0].w));
      dirs = {n, -n};
    }
    SupportPoint bestp{};
    double bestd = 0;
    for (const Vec3& d : dirs) {
      const SupportPoint sp = minkowski_support(a, b, d);
      if (const double dd = distance_to_hull(sp.w); dd > bestd) bestd = dd, bestp = sp;
    }
    if (bestd <= eps) return r;  // flat Minkowski difference: no volume to expand
    pts.push_back(bestp);
  }

  std::vector<Face> faces;
  const Vec3 centre = (pts[0].w + pts[1].w + pts[2].w + pts[3].w) * 0.25;
  static constexpr int kTet[4][3] = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
  for (const auto& t : kTet) {
    Face f;
    if (!epa_detail::make_face(pts, t[0], t[1], t[2], &f)) return r;
    if (dot(f.n, centre) > f.d) epa_detail::make_face(pts, t[0], t[2], t[1], &f);  // orient outward
    faces.push_back(f);
  }
  // The origin must lie inside the start: else faces face it from the wrong side, the horizon
  // stops being one loop and the polytope multiplies its faces without end.
  for (const Face& f : faces)
    if (f.d < -eps) return r;

  int best = -1;
  for (r.iterations = 1; r.iterations <= max_iterations; ++r.iterations) {
    best = -1;
    for (int i = 0; i < static_cast<int>(faces.size()); ++i)
      if (faces[i].alive && (best < 0 || faces[i].d < faces[best].d)) best = i;
    if (best < 0) return r;
    const Face f = faces[best];
    const SupportPoint sp = minkowski_support(a, b, f.n);
    if (dot(f.n, sp.w) - f.d <= eps) break;  // the face is on the boundary: converged
    const int iw = static_cast<int>(pts.size());
    pts.push_back(sp);
    std::vector<std::pair<int, int>> edges;
    for (Face& g : faces) {
      if (!g.alive || dot(g.n, sp.w) - g.d <= 0) continue;
      g.alive = false;
      for (int k = 0; k < 3; ++k) {
        const std::pair<int, int> e{g.v[k], g.v[(k + 1) % 3]};
        const auto rev = std::find(edges.begin(), edges.end(), std::pair<int, int>{e.second, e.first});
        if (rev != edges.end()) edges.erase(rev);  // shared by two removed faces: not horizon
        else edges.push_back(e);
      }
    }
    if (edges.empty()) break;
    // A convex polytope's horizon is a loop through fewer vertices than it has; a longer one
    // (rounding on a flat patch of the difference, as a cylinder's cap) means it broke down.
    if (edges.size() >= pts.size()) return r;
    for (const auto& [i, j] : edges) {
      Face g;
      if (epa_detail::make_face(pts, i, j, iw, &g)) faces.push_back(g);
    }
  }
  if (best < 0) return r;
  const Face& f = faces[best];
  // Barycentric weights of the origin's projection on the face, clamped against rounding.
  const Vec3 q = f.n * f.d;
  const Vec3 p0 = pts[f.v[0]].w, p1 = pts[f.v[1]].w, p2 = pts[f.v[2]].w;
  const double area = dot(cross(p1 - p0, p2 - p0), f.n);
  double l1 = dot(cross(q - p0, p2 - p0), f.n) / area;
  double l2 = dot(cross(p1 - p0, q - p0), f.n) / area;
  l1 = std::clamp(l1, 0.0, 1.0);
  l2 = std::clamp(l2, 0.0, 1.0 - l1);
  const double l0 = 1 - l1 - l2;
  r.point_a = pts[f.v[0]].a * l0 + pts[f.v[1]].a * l1 + pts[f.v[2]].a * l2;
  r.point_b = pts[f.v[0]].b * l0 + pts[f.v[1]].b * l1 + pts[f.v[2]].b * l2;
  r.depth = std::max(f.d, 0.0);
  r.normal = f.n;
  r.ok = std::isfinite(r.depth) && std::isfinite(r.point_a.x) && std::isfinite(r.point_b.x);
  return r;
}

}  // namespace talus
