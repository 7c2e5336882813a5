#include "talus/shape/convex_hull.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <stdexcept>

namespace talus {
namespace {

struct Tri {
  std::array<int, 3> v;
  Vec3 n;      // outward normal (unit)
  double d;    // offset
  bool alive = true;
};

Tri make_tri(const std::vector<Vec3>& p, int a, int b, int c) {
  const Vec3 n = normalized_or_zero(cross(p[b] - p[a], p[c] - p[a]));
  return {{a, b, c}, n, dot(n, p[a]), true};
}

int find_root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// Merges coplanar neighbouring triangles into polygons: clipping wants one face per plane.
std::vector<HullFace> merge_faces(const std::vector<Vec3>& v, const std::vector<std::array<int, 3>>& tris,
                                  double eps) {
  const int nt = static_cast<int>(tris.size());
  std::vector<Vec3> n(nt);
  std::vector<double> d(nt);
  for (int t = 0; t < nt; ++t) {
    n[t] = normalized_or_zero(cross(v[tris[t][1]] - v[tris[t][0]], v[tris[t][2]] - v[tris[t][0]]));
    d[t] = dot(n[t], v[tris[t][0]]);
  }
  std::map<std::pair<int, int>, int> edge_owner;
  for (int t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) edge_owner[{tris[t][k], tris[t][(k + 1) % 3]}] = t;
  std::vector<int> parent(nt);
  std::iota(parent.begin(), parent.end(), 0);
  for (int t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = tris[t][k], b = tris[t][(k + 1) % 3];
      const auto it = edge_owner.find({b, a});
      if (it == edge_owner.end()) continue;
      const int u = it->second;
      // Coplanar when every vertex of one triangle lies on the other's plane.
      bool coplanar = dot(n[t], n[u]) > 0;
      for (int j = 0; j < 3 && coplanar; ++j) coplanar = std::abs(dot(n[t], v[tris[u][j]]) - d[t]) <= eps;
      if (coplanar) parent[find_root(parent, t)] = find_root(parent, u);
    }
  std::map<int, std::vector<int>> groups;
  for (int t = 0; t < nt; ++t) groups[find_root(parent, t)].push_back(t);
  std::vector<HullFace> faces;
  for (const auto& [root, members] : groups) {
    std::set<std::pair<int, int>> edges;
    Vec3 area_normal;
    for (int t : members) {
      area_normal += cross(v[tris[t][1]] - v[tris[t][0]], v[tris[t][2]] - v[tris[t][0]]);
      for (int k = 0; k < 3; ++k) edges.insert({tris[t][k], tris[t][(k + 1) % 3]});
    }
    std::map<int, int> next;
    std::size_t boundary = 0;
    for (const auto& [a, b] : edges)
      if (!edges.count({b, a})) next[a] = b, ++boundary;
    HullFace f;
    f.normal = normalized_or_zero(area_normal);
    int start = next.begin()->first, cur = start;
    do {
      f.vertices.push_back(cur);
      const auto it = next.find(cur);
      cur = it == next.end() ? -1 : it->second;
    } while (cur != start && cur >= 0 && f.vertices.size() <= boundary);
    if (cur != start || f.vertices.size() != boundary || next.size() != boundary) {
      // Not one simple loop (a pinched group from near-coplanar rounding): keep its triangles.
      for (int tr : members) {
        HullFace g{{tris[tr][0], tris[tr][1], tris[tr][2]}, n[tr], d[tr]};
        faces.push_back(std::move(g));
      }
      continue;
    }
    for (int i : f.vertices) f.offset += dot(f.normal, v[i]);
    f.offset /= static_cast<double>(f.vertices.size());
    faces.push_back(std::move(f));
  }
  return faces;
}

}  // namespace

ConvexHull build_convex_hull(const std::vector<Vec3>& input) {
  // Near-duplicate points (e.g. erosion vertices where many faces meet) make sliver faces.
  std::vector<Vec3> points;
  {
    Vec3 lo = input.at(0), hi = input.at(0);
    for (const Vec3& p : input)
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
    const double merge2 = 1e-18 * norm2(hi - lo);  // (1e-9 x size)^2
    for (const Vec3& p : input)
      if (std::none_of(points.begin(), points.end(), [&](const Vec3& q) { return norm2(p - q) <= merge2; }))
        points.push_back(p);
  }
  const int np = static_cast<int>(points.size());
  if (np < 4) throw std::invalid_argument("convex hull: need at least 4 points");
  Vec3 lo = points[0], hi = points[0];
  for (const Vec3& p : points)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  const double scale = norm(hi - lo);
  const double eps = 1e-10 * scale;  // points closer than this to a face plane are on it

  // Initial tetrahedron from extreme points, so it is as far from degenerate as the cloud allows.
  int i0 = 0;
  for (int i = 1; i < np; ++i)
    if (points[i].x < points[i0].x) i0 = i;
  auto farthest = [&](auto&& dist) {
    int best = -1;
    double bd = -1;
    for (int i = 0; i < np; ++i)
      if (const double di = dist(points[i]); di > bd) bd = di, best = i;
    return std::pair{best, bd};
  };
  const auto [i1, d1] = farthest([&](const Vec3& p) { return norm(p - points[i0]); });
  const Vec3 e01 = normalized_or_zero(points[i1] - points[i0]);
  const auto [i2, d2] = farthest([&](const Vec3& p) { return norm(cross(p - points[i0], e01)); });
  const Vec3 n012 = normalized_or_zero(cross(points[i1] - points[i0], points[i2] - points[i0]));
  const auto [i3, d3] = farthest([&](const Vec3& p) { return std::abs(dot(p - points[i0], n012)); });
  if (d1 <= eps || d2 <= 1e-8 * scale || d3 <= 1e-8 * scale)
    throw std::invalid_argument("convex hull: points are degenerate (collinear or coplanar)");

  const Vec3 inside = (points[i0] + points[i1] + points[i2] + points[i3]) * 0.25;
  std::vector<Tri> tris;
  auto add = [&](int a, int b, int c) {
    Tri t = make_tri(points, a, b, c);
    if (dot(t.n, inside) > t.d) t = make_tri(points, a, c, b);  // orient outward
    tris.push_back(t);
  };
  add(i0, i1, i2);
  add(i0, i1, i3);
  add(i0, i2, i3);
  add(i1, i2, i3);

  // Far points first: most interior points then fall inside early and are skipped.
  std::vector<int> order(np);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return norm2(points[a] - inside) > norm2(points[b] - inside); });
  for (int ip : order) {
    if (ip == i0 || ip == i1 || ip == i2 || ip == i3) continue;
    const Vec3& p = points[ip];
    std::set<std::pair<int, int>> visible_edges;
    std::vector<int> visible;
    for (int t = 0; t < static_cast<int>(tris.size()); ++t)
      if (tris[t].alive && dot(tris[t].n, p) - tris[t].d > eps) visible.push_back(t);
    if (visible.empty()) continue;
    for (int t : visible)
      for (int k = 0; k < 3; ++k) visible_edges.insert({tris[t].v[k], tris[t].v[(k + 1) % 3]});
    for (int t : visible) tris[t].alive = false;
    std::erase_if(tris, [](const Tri& t) { return !t.alive; });  // dead faces would slow every later scan
    for (const auto& [a, b] : visible_edges)
      if (!visible_edges.count({b, a})) tris.push_back(make_tri(points, a, b, ip));  // horizon edge
  }

  ConvexHull hull;
  std::vector<int> remap(np, -1);
  for (const Tri& t : tris) {
    if (!t.alive) continue;
    std::array<int, 3> r{};
    for (int k = 0; k < 3; ++k) {
      if (remap[t.v[k]] < 0) {
        remap[t.v[k]] = static_cast<int>(hull.vertices.size());
        hull.vertices.push_back(points[t.v[k]]);
      }
      r[k] = remap[t.v[k]];
    }
    hull.triangles.push_back(r);
  }
  hull.faces = merge_faces(hull.vertices, hull.triangles, 1e-9 * scale);
  return hull;
}

}  // namespace talus
