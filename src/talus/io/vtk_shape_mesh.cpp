#include "talus/io/vtk_shape_mesh.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace talus::io {

namespace {

template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

// Every geometry is convex and holds its local origin, so a triangle faces outwards exactly
// when its normal points away from the origin; this fixes the winding of any generated fan.
void add_outward(SurfaceMesh& m, int a, int b, int c) {
  const Vec3& pa = m.vertices[a];
  const Vec3 n = cross(m.vertices[b] - pa, m.vertices[c] - pa);
  const Vec3 centroid = (pa + m.vertices[b] + m.vertices[c]) / 3.0;
  if (dot(n, centroid) < 0) std::swap(b, c);
  m.triangles.push_back({a, b, c});
}

void add_fan(SurfaceMesh& m, const std::vector<int>& polygon) {
  for (std::size_t k = 1; k + 1 < polygon.size(); ++k) add_outward(m, polygon[0], polygon[k], polygon[k + 1]);
}

SurfaceMesh box_mesh(const Box& b) {
  SurfaceMesh m;
  const Vec3 h = b.half_extents;
  for (int k = 0; k < 8; ++k)  // bit 0: x, bit 1: y, bit 2: z
    m.vertices.push_back({k & 1 ? h.x : -h.x, k & 2 ? h.y : -h.y, k & 4 ? h.z : -h.z});
  for (const std::vector<int>& quad : {std::vector<int>{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                       {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}})
    add_fan(m, quad);
  return m;
}

SurfaceMesh cylinder_mesh(const Cylinder& c, int sides) {
  SurfaceMesh m;
  sides = std::max(sides, 3);
  for (int ring = 0; ring < 2; ++ring)
    for (int k = 0; k < sides; ++k) {
      const double a = 2 * std::numbers::pi * k / sides;
      m.vertices.push_back({c.radius * std::cos(a), c.radius * std::sin(a),
                            ring == 0 ? -c.half_height : c.half_height});
    }
  for (int k = 0; k < sides; ++k) {
    const int k1 = (k + 1) % sides;
    add_outward(m, k, k1, sides + k1);
    add_outward(m, k, sides + k1, sides + k);
  }
  std::vector<int> bottom(sides), top(sides);
  for (int k = 0; k < sides; ++k) bottom[k] = k, top[k] = sides + k;
  add_fan(m, bottom);
  add_fan(m, top);
  return m;
}

SurfaceMesh polyhedron_mesh(const ConvexPolyhedron& p) {
  SurfaceMesh m;
  m.vertices = p.hull.vertices;
  if (p.hull.faces.empty()) {
    for (const auto& t : p.hull.triangles) add_outward(m, t[0], t[1], t[2]);
  } else {
    for (const HullFace& f : p.hull.faces) add_fan(m, f.vertices);
  }
  return m;
}

SurfaceMesh sphere_mesh(const Sphere& s, int rings, int segments) {
  SurfaceMesh m;
  rings = std::max(rings, 2);
  segments = std::max(segments, 3);
  m.vertices.push_back({0, 0, -s.radius});  // south pole: 0
  for (int r = 1; r < rings; ++r) {
    const double theta = std::numbers::pi * r / rings;  // from the south pole
    for (int k = 0; k < segments; ++k) {
      const double phi = 2 * std::numbers::pi * k / segments;
      m.vertices.push_back({s.radius * std::sin(theta) * std::cos(phi),
                            s.radius * std::sin(theta) * std::sin(phi), -s.radius * std::cos(theta)});
    }
  }
  const int north = static_cast<int>(m.vertices.size());
  m.vertices.push_back({0, 0, s.radius});
  auto ring_vertex = [&](int r, int k) { return 1 + (r - 1) * segments + k % segments; };
  for (int k = 0; k < segments; ++k) {
    add_outward(m, 0, ring_vertex(1, k), ring_vertex(1, k + 1));
    add_outward(m, north, ring_vertex(rings - 1, k), ring_vertex(rings - 1, k + 1));
    for (int r = 1; r + 1 < rings; ++r) {
      add_outward(m, ring_vertex(r, k), ring_vertex(r, k + 1), ring_vertex(r + 1, k + 1));
      add_outward(m, ring_vertex(r, k), ring_vertex(r + 1, k + 1), ring_vertex(r + 1, k));
    }
  }
  return m;
}

}  // namespace

SurfaceMesh triangulate(const ConvexGeometry& geometry, const MeshResolution& res) {
  SurfaceMesh m = std::visit(
      Overloaded{[&](const Sphere& s) { return sphere_mesh(s, res.sphere_rings, res.sphere_segments); },
                 [](const Box& b) { return box_mesh(b); },
                 [&](const Cylinder& c) { return cylinder_mesh(c, res.cylinder_sides); },
                 [](const ConvexPolyhedron& p) { return polyhedron_mesh(p); }},
      geometry);
  m.part.assign(m.triangles.size(), 0);
  return m;
}

SurfaceMesh triangulate(const CompositeShape& shape, const MeshResolution& res) {
  SurfaceMesh out;
  for (std::size_t p = 0; p < shape.parts.size(); ++p) {
    const CompositePart& part = shape.parts[p];
    const SurfaceMesh m = triangulate(part.shape.geometry, res);
    const int base = static_cast<int>(out.vertices.size());
    for (const Vec3& v : m.vertices) out.vertices.push_back(part.pose.to_parent(v));
    for (const auto& t : m.triangles) {
      out.triangles.push_back({base + t[0], base + t[1], base + t[2]});
      out.part.push_back(static_cast<int>(p));
    }
  }
  return out;
}

bool is_plain_sphere(const CompositeShape& shape) {
  return shape.parts.size() == 1 && shape.parts[0].shape.kind() == ShapeKind::kSphere &&
         shape.parts[0].pose.position == Vec3{};
}

}  // namespace talus::io
