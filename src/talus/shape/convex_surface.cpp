#include "talus/shape/convex_surface.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "talus/shape/convex_hull.h"

namespace talus {

namespace {

std::string point_text(const Vec3& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.7g %.7g %.7g)", p.x, p.y, p.z);
  return buf;
}

std::string short_number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

void check_closed(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> runs;  // directed edge -> triangles running along it
  for (const std::array<int, 3>& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++runs[{t[k], t[(k + 1) % 3]}];
  for (const auto& [edge, count] : runs) {
    const auto [a, b] = edge;
    const std::string name = "edge " + point_text(mesh.vertices[a]) + "-" + point_text(mesh.vertices[b]);
    if (count > 1)
      throw std::invalid_argument("the surface is not closed: " + name + " is run along in the same direction by " +
                                  std::to_string(count) + " triangles (neighbours facing opposite ways, or more than two "
                                  "triangles on one edge)");
    if (!runs.contains({b, a}))
      throw std::invalid_argument("the surface is not closed: " + name + " belongs to 1 triangle only (a hole or a crack)");
  }
}

double enclosed_volume(const std::vector<Vec3>& v, const std::vector<std::array<int, 3>>& triangles) {
  double six_volume = 0;
  for (const std::array<int, 3>& t : triangles) six_volume += dot(v[t[0]], cross(v[t[1]], v[t[2]]));
  return six_volume / 6;
}

void check_convex(const TriangleMesh& mesh) {
  ConvexHull hull;
  try {
    hull = build_convex_hull(mesh.vertices);
  } catch (const std::invalid_argument&) {
    throw std::invalid_argument("the vertices lie in a plane (or a line): a polyhedron needs volume");
  }
  const double skin = 1e-6 * bounding_diagonal(mesh.vertices);
  for (const Vec3& p : mesh.vertices) {
    double depth = std::numeric_limits<double>::infinity();  // how far inside the hull's nearest face
    for (const HullFace& face : hull.faces) depth = std::min(depth, face.offset - dot(face.normal, p));
    if (depth > skin)
      throw std::invalid_argument("the surface is not convex: vertex " + point_text(p) + " lies " + short_number(depth) +
                                  " inside the convex hull of the vertices");
  }
  double hull_area = 0;
  for (const std::array<int, 3>& t : hull.triangles) {
    const std::vector<Vec3>& h = hull.vertices;
    hull_area += 0.5 * norm(cross(h[t[1]] - h[t[0]], h[t[2]] - h[t[0]]));
  }
  // Closed and consistently oriented, the mesh may still face inward: its volume is then negative.
  const double volume = std::abs(enclosed_volume(mesh.vertices, mesh.triangles));
  const double hull_volume = enclosed_volume(hull.vertices, hull.triangles);
  if (std::abs(hull_volume - volume) > skin * hull_area)
    throw std::invalid_argument("the surface is not convex: it encloses " + short_number(volume) +
                                " where the convex hull of its vertices holds " + short_number(hull_volume) +
                                " (triangles cut through the hull between its vertices)");
}

}  // namespace

void check_closed_convex_surface(const TriangleMesh& mesh) {
  check_closed(mesh);
  check_convex(mesh);
}

}  // namespace talus
