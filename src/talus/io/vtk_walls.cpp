#include "talus/io/vtk_walls.h"

#include <algorithm>
#include <cmath>

#include "talus/io/atomic_file.h"
#include "talus/io/vtk_xml.h"

namespace talus::io {

namespace {

// A unit vector perpendicular to the unit vector n.
Vec3 any_perpendicular(const Vec3& n) {
  const Vec3 helper = std::abs(n.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  return normalized_or_zero(cross(n, helper));
}

}  // namespace

std::vector<Vec3> clip_plane_to_box(const Vec3& origin, const Vec3& normal_in, const Aabb& box) {
  const Vec3 n = normalized_or_zero(normal_in);
  if (n == Vec3{}) return {};
  const double tol = 1e-9 * norm(box.hi - box.lo);
  auto corner = [&](int k) {
    return Vec3{k & 1 ? box.hi.x : box.lo.x, k & 2 ? box.hi.y : box.lo.y, k & 4 ? box.hi.z : box.lo.z};
  };
  auto dist = [&](const Vec3& p) { return dot(n, p - origin); };

  std::vector<Vec3> pts;
  for (int k = 0; k < 8; ++k)  // corners on the plane (a plane along a box face keeps 4)
    if (std::abs(dist(corner(k))) <= tol) pts.push_back(corner(k));
  for (int k = 0; k < 8; ++k)
    for (int axis = 0; axis < 3; ++axis) {
      if (k & (1 << axis)) continue;  // each edge once, from its low end
      const Vec3 a = corner(k), b = corner(k | (1 << axis));
      const double da = dist(a), db = dist(b);
      if ((da < -tol && db > tol) || (da > tol && db < -tol)) pts.push_back(a + (b - a) * (da / (da - db)));
    }
  if (pts.size() < 3) return {};

  Vec3 c;
  for (const Vec3& p : pts) c += p;
  c = c / static_cast<double>(pts.size());
  const Vec3 u = any_perpendicular(n);
  const Vec3 v = cross(n, u);  // u x v = n: increasing angle is counter-clockwise about n
  std::sort(pts.begin(), pts.end(), [&](const Vec3& p, const Vec3& q) {
    return std::atan2(dot(p - c, v), dot(p - c, u)) < std::atan2(dot(q - c, v), dot(q - c, u));
  });
  // Drop near-duplicates (a plane through a corner meets several edges there).
  std::vector<Vec3> out;
  for (const Vec3& p : pts)
    if (out.empty() || norm(p - out.back()) > tol) out.push_back(p);
  while (out.size() > 1 && norm(out.front() - out.back()) <= tol) out.pop_back();
  if (out.size() < 3) return {};
  return out;
}

void write_walls_vtu(const std::filesystem::path& path, const std::vector<Wall>& walls, double time,
                     const Aabb& box) {
  VtuGrid grid;
  std::vector<std::int32_t> index, material;
  std::vector<Vec3> normal, velocity;
  std::vector<std::uint8_t> bounded;
  for (std::size_t w = 0; w < walls.size(); ++w) {
    const Wall& wall = walls[w];
    if (!wall.active(time)) continue;
    const Vec3 o = wall.origin_at(time);
    std::vector<Vec3> polygon;
    if (wall.bounded) {
      const Vec3 u = wall.axis_u * wall.half_extent_u, v = wall.axis_v * wall.half_extent_v;
      polygon = {o - u - v, o + u - v, o + u + v, o - u + v};
      if (dot(cross(wall.axis_u, wall.axis_v), wall.normal) < 0) std::reverse(polygon.begin(), polygon.end());
    } else {
      polygon = clip_plane_to_box(o, wall.normal, box);
    }
    if (polygon.empty()) continue;
    std::vector<std::int64_t> ids;
    for (const Vec3& p : polygon) ids.push_back(grid.add_point(p));
    grid.add_cell(ids.size() == 4 ? VtkCellType::kQuad : VtkCellType::kPolygon, ids);
    index.push_back(static_cast<std::int32_t>(w));
    material.push_back(wall.material);
    normal.push_back(wall.normal);
    velocity.push_back(wall.velocity_at(time));
    bounded.push_back(wall.bounded ? 1 : 0);
  }
  using W = VtuGrid::Where;
  grid.add_array(W::kCell, "wall", 1, index);
  grid.add_array(W::kCell, "normal", normal);
  grid.add_array(W::kCell, "velocity", velocity);
  grid.add_array(W::kCell, "material", 1, material);
  grid.add_array(W::kCell, "bounded", 1, bounded);
  atomic_write(path, grid.serialize());
}

}  // namespace talus::io
