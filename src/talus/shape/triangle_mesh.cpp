#include "talus/shape/triangle_mesh.h"

#include <algorithm>
#include <numeric>

namespace talus {

double bounding_diagonal(const std::vector<Vec3>& points) {
  if (points.empty()) return 0;
  Vec3 lo = points[0], hi = points[0];
  for (const Vec3& p : points)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  return norm(hi - lo);
}

TriangleMesh welded(const TriangleMesh& raw) {
  const double merge = 1e-9 * bounding_diagonal(raw.vertices);
  // Each point joins the first point (in x order) within `merge`; sorted along x, a point only
  // needs comparing with those within `merge` in x.
  const int n = static_cast<int>(raw.vertices.size());
  std::vector<int> by_x(n);
  std::iota(by_x.begin(), by_x.end(), 0);
  std::stable_sort(by_x.begin(), by_x.end(), [&](int a, int b) { return raw.vertices[a].x < raw.vertices[b].x; });
  std::vector<int> representative(n);
  std::vector<int> kept;  // representatives so far, in x order
  for (int i : by_x) {
    const Vec3& p = raw.vertices[i];
    representative[i] = i;
    for (auto q = kept.rbegin(); q != kept.rend() && p.x - raw.vertices[*q].x <= merge; ++q)
      if (norm2(p - raw.vertices[*q]) <= merge * merge) {
        representative[i] = *q;
        break;
      }
    if (representative[i] == i) kept.push_back(i);
  }

  TriangleMesh mesh;
  std::vector<int> renumbered(n, -1);
  for (const std::array<int, 3>& t : raw.triangles) {
    const std::array<int, 3> r{representative[t[0]], representative[t[1]], representative[t[2]]};
    if (r[0] == r[1] || r[1] == r[2] || r[2] == r[0]) continue;
    std::array<int, 3> out{};
    for (int k = 0; k < 3; ++k) {
      if (renumbered[r[k]] < 0) {
        renumbered[r[k]] = static_cast<int>(mesh.vertices.size());
        mesh.vertices.push_back(raw.vertices[r[k]]);
      }
      out[k] = renumbered[r[k]];
    }
    mesh.triangles.push_back(out);
  }
  return mesh;
}

}  // namespace talus
