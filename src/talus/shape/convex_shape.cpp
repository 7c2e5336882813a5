#include "talus/shape/convex_shape.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace talus {
namespace {

template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

// Exact erosion of a polyhedron by c: the intersection of the face half-spaces moved in by c.
// Computed through polar duality about an interior point z: plane n.x <= e (e = d - c - n.z > 0)
// maps to the dual point n / e; each face of the dual hull maps back to one primal vertex.
ConvexHull erode(const ConvexHull& h, double c) {
  if (c == 0) return h;
  Vec3 z;
  for (const Vec3& v : h.vertices) z += v;
  z = z / static_cast<double>(h.vertices.size());
  std::vector<Vec3> dual;
  for (const HullFace& f : h.faces) {
    const double e = f.offset - c - dot(f.normal, z);
    if (e <= 0) throw std::invalid_argument("make_polyhedron: crust too thick for the shape");
    dual.push_back(f.normal / e);
  }
  const ConvexHull dh = build_convex_hull(dual);
  std::vector<Vec3> primal;
  for (const HullFace& f : dh.faces) {
    if (f.offset <= 0) throw std::invalid_argument("make_polyhedron: crust erosion failed");
    primal.push_back(z + f.normal / f.offset);
  }
  return build_convex_hull(primal);
}

}  // namespace

ConvexShape make_sphere(double radius) {
  if (!(radius > 0)) throw std::invalid_argument("make_sphere: radius must be > 0");
  ConvexShape s{Sphere{radius}, Sphere{0.0}, radius, radius};
  return s;
}

ConvexShape make_box(const Vec3& half_extents, double crust) {
  const double hmin = std::min({half_extents.x, half_extents.y, half_extents.z});
  if (!(hmin > 0) || crust < 0 || crust >= hmin)
    throw std::invalid_argument("make_box: need 0 <= crust < smallest half extent");
  const Vec3 core = half_extents - Vec3{crust, crust, crust};
  return {Box{half_extents}, Box{core}, crust, norm(half_extents)};
}

ConvexShape make_cylinder(double radius, double half_height, double crust) {
  if (!(radius > 0 && half_height > 0) || crust < 0 || crust >= std::min(radius, half_height))
    throw std::invalid_argument("make_cylinder: need 0 <= crust < min(radius, half_height)");
  return {Cylinder{radius, half_height}, Cylinder{radius - crust, half_height - crust}, crust,
          std::hypot(radius, half_height)};
}

ConvexShape make_polyhedron(const std::vector<Vec3>& points, double crust) {
  ConvexHull hull = build_convex_hull(points);
  for (const HullFace& f : hull.faces)
    if (f.offset <= 0) throw std::invalid_argument("make_polyhedron: local origin not inside the hull");
  if (crust < 0) throw std::invalid_argument("make_polyhedron: crust must be >= 0");
  ConvexHull core = erode(hull, crust);
  ConvexShape s{ConvexPolyhedron{std::move(hull)}, ConvexPolyhedron{std::move(core)}, crust, 0};
  s.bounding_radius = bounding_radius(s.geometry);
  return s;
}

Vec3 support(const ConvexGeometry& g, const Vec3& d) {
  return std::visit(
      Overloaded{
          [&](const Sphere& s) { return normalized_or_zero(d) * s.radius; },
          [&](const Box& b) {
            return Vec3{d.x >= 0 ? b.half_extents.x : -b.half_extents.x,
                        d.y >= 0 ? b.half_extents.y : -b.half_extents.y,
                        d.z >= 0 ? b.half_extents.z : -b.half_extents.z};
          },
          [&](const Cylinder& c) {
            const double r = std::hypot(d.x, d.y);
            const double k = r > 0 ? c.radius / r : 0.0;
            return Vec3{d.x * k, d.y * k, d.z >= 0 ? c.half_height : -c.half_height};
          },
          [&](const ConvexPolyhedron& p) {
            // Linear scan: a few hundred vertices at most; hill climbing would pay off beyond.
            const std::vector<Vec3>& v = p.hull.vertices;
            std::size_t best = 0;
            double bd = dot(v[0], d);
            for (std::size_t i = 1; i < v.size(); ++i)
              if (const double di = dot(v[i], d); di > bd) bd = di, best = i;
            return v[best];
          }},
      g);
}

double bounding_radius(const ConvexGeometry& g) {
  return std::visit(Overloaded{[](const Sphere& s) { return s.radius; },
                               [](const Box& b) { return norm(b.half_extents); },
                               [](const Cylinder& c) { return std::hypot(c.radius, c.half_height); },
                               [](const ConvexPolyhedron& p) {
                                 double r = 0;
                                 for (const Vec3& v : p.hull.vertices) r = std::max(r, norm(v));
                                 return r;
                               }},
                    g);
}

namespace {
template <class SupportFn>
Aabb aabb_from_support(const Pose& pose, SupportFn&& sup) {
  // Exact extent along each world axis: the support along +-e_k.
  Aabb box;
  for (int k = 0; k < 3; ++k) {
    Vec3 e;
    e[k] = 1;
    box.hi[k] = pose.to_parent(sup(pose.orientation.rotate_inverse(e)))[k];
    box.lo[k] = pose.to_parent(sup(pose.orientation.rotate_inverse(-e)))[k];
  }
  return box;
}
}  // namespace

Aabb aabb(const ConvexShape& s, const Pose& pose) {
  return aabb_from_support(pose, [&](const Vec3& d) { return support(s, d); });
}

Aabb aabb(const ConvexGeometry& g, const Pose& pose) {
  return aabb_from_support(pose, [&](const Vec3& d) { return support(g, d); });
}

bool contains(const ConvexGeometry& g, const Vec3& p) {
  return std::visit(
      Overloaded{[&](const Sphere& s) { return norm2(p) <= s.radius * s.radius; },
                 [&](const Box& b) {
                   return std::abs(p.x) <= b.half_extents.x && std::abs(p.y) <= b.half_extents.y &&
                          std::abs(p.z) <= b.half_extents.z;
                 },
                 [&](const Cylinder& c) {
                   return std::abs(p.z) <= c.half_height && p.x * p.x + p.y * p.y <= c.radius * c.radius;
                 },
                 [&](const ConvexPolyhedron& h) {
                   for (const HullFace& f : h.hull.faces)
                     if (dot(f.normal, p) > f.offset) return false;
                   return true;
                 }},
      g);
}

}  // namespace talus
