#include "talus/collide/gjk_simplex.h"

#include <cmath>
#include <limits>

namespace talus {
namespace {

// Closest point of a sub-simplex, with weights on the indices it keeps.
struct Closest {
  Vec3 v;
  int n = 0;
  std::array<int, 4> idx{};
  std::array<double, 4> lambda{};
};

Closest point1(const Simplex& s, int i) { return {s.p[i].w, 1, {i}, {1.0}}; }

Closest segment(const Simplex& s, int i, int j) {
  const Vec3 a = s.p[i].w, ab = s.p[j].w - a;
  const double len2 = norm2(ab);
  const double t = len2 > 0 ? -dot(a, ab) / len2 : 0.0;
  if (t <= 0) return point1(s, i);
  if (t >= 1) return point1(s, j);
  return {a + ab * t, 2, {i, j}, {1 - t, t}};
}

Closest best(const Closest& x, const Closest& y) { return norm2(y.v) < norm2(x.v) ? y : x; }

Closest triangle(const Simplex& s, int i, int j, int k) {
  const Vec3 a = s.p[i].w, b = s.p[j].w, c = s.p[k].w;
  const Vec3 ab = b - a, ac = c - a;
  const double d1 = -dot(ab, a), d2 = -dot(ac, a);
  if (d1 <= 0 && d2 <= 0) return point1(s, i);
  const double d3 = -dot(ab, b), d4 = -dot(ac, b);
  if (d3 >= 0 && d4 <= d3) return point1(s, j);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return segment(s, i, j);
  const double d5 = -dot(ab, c), d6 = -dot(ac, c);
  if (d6 >= 0 && d5 <= d6) return point1(s, k);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return segment(s, i, k);
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return segment(s, j, k);
  const double denom = va + vb + vc;
  // Collinear (flat) triangle: the weights are meaningless, its edges carry the answer.
  if (!(denom > 1e-14 * norm2(ab) * norm2(ac)))
    return best(best(segment(s, i, j), segment(s, i, k)), segment(s, j, k));
  const double v = vb / denom, w = vc / denom;
  return {a + ab * v + ac * w, 3, {i, j, k}, {1 - v - w, v, w}};
}

Closest tetrahedron(const Simplex& s, bool* inside) {
  static constexpr int kFaces[4][4] = {{0, 1, 2, 3}, {0, 1, 3, 2}, {0, 2, 3, 1}, {1, 2, 3, 0}};  // face + opposite
  const Vec3 a = s.p[0].w;
  const double vol6 = dot(s.p[1].w - a, cross(s.p[2].w - a, s.p[3].w - a));
  double scale = 0;
  for (int i = 1; i < 4; ++i) scale = std::max(scale, norm(s.p[i].w - a));
  const bool flat = std::abs(vol6) <= 1e-12 * scale * scale * scale;
  Closest out;
  out.v = Vec3{std::numeric_limits<double>::infinity(), 0, 0};
  bool outside_any = false;
  for (const auto& f : kFaces) {
    const Vec3 p0 = s.p[f[0]].w;
    const Vec3 n = cross(s.p[f[1]].w - p0, s.p[f[2]].w - p0);
    const double so = -dot(n, p0), sv = dot(n, s.p[f[3]].w - p0);
    if (!flat && so * sv >= 0) continue;  // origin on the inner side of this face
    outside_any = outside_any || !flat;
    out = best(out, triangle(s, f[0], f[1], f[2]));
  }
  if (!flat && !outside_any) {
    *inside = true;
    return {Vec3{}, 4, {0, 1, 2, 3}, {0.25, 0.25, 0.25, 0.25}};
  }
  if (flat && norm(out.v) <= 1e-12 * scale) *inside = true;
  return out;
}

}  // namespace

Vec3 reduce_simplex(Simplex& s, bool* inside) {
  *inside = false;
  Closest c;
  switch (s.size) {
    case 1: c = point1(s, 0); break;
    case 2: c = segment(s, 0, 1); break;
    case 3: c = triangle(s, 0, 1, 2); break;
    default: c = tetrahedron(s, inside); break;
  }
  if (*inside && c.n == 4) {
    s.lambda = c.lambda;
    return c.v;
  }
  // In place: the kept indices rise, so each point moves down onto one already read.
  for (int k = 0; k < c.n; ++k) {
    if (c.idx[k] != k) s.p[k] = s.p[c.idx[k]];
    s.lambda[k] = c.lambda[k];
  }
  for (int k = c.n; k < 4; ++k) s.lambda[k] = 0;
  s.size = c.n;
  return c.v;
}

}  // namespace talus
