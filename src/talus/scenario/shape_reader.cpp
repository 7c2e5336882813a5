#include "talus/scenario/shape_reader.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "talus/io/number_format.h"
#include "talus/scenario/mesh_shape_reader.h"
#include "talus/shape/convex_hull.h"

namespace talus {

namespace {

using io::ScenarioFile;

double crust_of(const ScenarioFile& f, const std::string& key, double smallest_half) {
  const double crust = f.get_or<double>(key + ".crust", 0.05 * smallest_half, io::non_negative);
  if (crust >= smallest_half)
    f.fail(key + ".crust", "must be smaller than the shape's smallest half dimension (" +
                               io::format_double(smallest_half) + " m)");
  return crust;
}

// A convex part placed in its body by `pose`: the polyhedron's vertices are taken about their
// centroid (the hull must hold its local origin), which shifts the part's place by as much.
struct PlacedPart {
  ConvexShape shape;
  Vec3 offset;  ///< m, the part's local origin in the frame the user gave its vertices in
};

// The corners as a list, `vertices = [[x, y, z], ...]`.
std::vector<Vec3> read_vertex_list(const ScenarioFile& f, const std::string& key) {
  const std::size_t n = f.array_size(key + ".vertices");
  if (n < 4) f.fail(key + ".vertices", "a polyhedron needs at least 4 vertices [[x, y, z], ...], got " + std::to_string(n));
  std::vector<Vec3> v(n);
  for (std::size_t k = 0; k < n; ++k) v[k] = f.get<Vec3>(key + ".vertices[" + std::to_string(k) + "]");
  return v;
}

PlacedPart read_polyhedron(const ScenarioFile& f, const std::string& key) {
  const bool from_mesh = f.has(key + ".mesh");
  if (from_mesh && f.has(key + ".vertices")) f.fail(key + ".mesh", "give either vertices or mesh, not both");
  if (!from_mesh) f.explain_if_unread(key + ".mesh_scale", "it scales a mesh, and this polyhedron gives vertices");
  const std::string source = key + (from_mesh ? ".mesh" : ".vertices");
  std::vector<Vec3> v = from_mesh ? read_mesh_vertices(f, key) : read_vertex_list(f, key);
  Vec3 centroid;
  for (const Vec3& x : v) centroid += x;
  centroid = centroid / static_cast<double>(v.size());
  for (Vec3& x : v) x -= centroid;
  ConvexHull hull;
  try {
    hull = build_convex_hull(v);
  } catch (const std::invalid_argument&) {
    f.fail(source, "the vertices lie in a plane (or a line): a polyhedron needs volume");
  }
  double inner = std::numeric_limits<double>::infinity();  // the centroid's distance to the nearest face
  for (const HullFace& face : hull.faces) inner = std::min(inner, face.offset);
  const double crust = crust_of(f, key, inner);
  return {make_polyhedron(v, crust), centroid};
}

PlacedPart read_convex(const ScenarioFile& f, const std::string& key, const std::string& shape) {
  if (shape == "box") {
    const Vec3 h = f.get<Vec3>(key + ".half_extents", io::positive);
    return {make_box(h, crust_of(f, key, std::min({h.x, h.y, h.z}))), {}};
  }
  if (shape == "cylinder") {
    const double radius = f.get<double>(key + ".radius", io::positive);
    const double half_height = 0.5 * f.get<double>(key + ".height", io::positive);
    return {make_cylinder(radius, half_height, crust_of(f, key, std::min(radius, half_height))), {}};
  }
  if (shape == "sphere") return {make_sphere(f.get<double>(key + ".radius", io::positive)), {}};
  return read_polyhedron(f, key);
}

Quat read_orientation(const ScenarioFile& f, const std::string& key) {
  if (!f.has(key)) return {};
  const std::vector<double> v = f.get<std::vector<double>>(key);
  if (v.size() != 4 || v[0] * v[0] + v[1] * v[1] + v[2] * v[2] + v[3] * v[3] == 0)
    f.fail(key, "expected a quaternion [w, x, y, z]");
  return Quat{v[0], v[1], v[2], v[3]}.normalized();
}

// The rotation taking z onto the unit vector `d`.
Quat z_onto(const Vec3& d) {
  const Vec3 z{0, 0, 1};
  const Vec3 axis = cross(z, d);
  const double s = norm(axis), c = dot(z, d);
  if (s < 1e-12) return c > 0 ? Quat{} : Quat::from_axis_angle({1, 0, 0}, std::numbers::pi);
  return Quat::from_axis_angle(axis / s, std::atan2(s, c));
}

// Named shapes of the granular literature, as composites of convex parts.
CompositeShape read_named(const ScenarioFile& f, const std::string& key, const std::string& shape) {
  CompositeShape c;
  if (shape == "hexapod") {  // a 3-D cross: three square rods along x, y and z, crossing at their centres
    const double length = f.get<double>(key + ".length", io::positive), width = f.get<double>(key + ".width", io::positive);
    if (width >= length) f.fail(key + ".width", "must be smaller than the length");
    const double crust = crust_of(f, key, 0.5 * width);
    const Vec3 h{0.5 * width, 0.5 * width, 0.5 * length};
    c.add(make_box(h, crust), Pose{});
    c.add(make_box(h, crust), Pose{{}, Quat::from_axis_angle({1, 0, 0}, 0.5 * std::numbers::pi)});
    c.add(make_box(h, crust), Pose{{}, Quat::from_axis_angle({0, 1, 0}, 0.5 * std::numbers::pi)});
  } else if (shape == "tetrapod") {  // four cylindrical arms from the centre to a tetrahedron's corners
    const double arm = f.get<double>(key + ".length", io::positive), radius = f.get<double>(key + ".radius", io::positive);
    if (radius >= arm) f.fail(key + ".radius", "must be smaller than the arm length");
    const double crust = crust_of(f, key, std::min(radius, 0.5 * arm));
    for (const Vec3& corner : {Vec3{1, 1, 1}, Vec3{1, -1, -1}, Vec3{-1, 1, -1}, Vec3{-1, -1, 1}}) {
      const Vec3 d = corner / std::sqrt(3.0);
      c.add(make_cylinder(radius, 0.5 * arm, crust), Pose{0.5 * arm * d, z_onto(d)});
    }
  } else if (shape == "stellated_octahedron") {  // two regular tetrahedra in the corners of one cube
    const double a = 0.5 * f.get<double>(key + ".size", io::positive);  // the cube's half side
    const std::vector<Vec3> first{{a, a, a}, {a, -a, -a}, {-a, a, -a}, {-a, -a, a}};
    std::vector<Vec3> second;
    for (const Vec3& v : first) second.push_back(-1.0 * v);
    const double crust = crust_of(f, key, a / 3);  // a regular tetrahedron's inradius
    c.add(make_polyhedron(first, crust), Pose{});
    c.add(make_polyhedron(second, crust), Pose{});
  } else {  // rod: a spherocylinder along z, `length` between its caps' centres
    const double length = f.get<double>(key + ".length", io::positive), radius = f.get<double>(key + ".radius", io::positive);
    const double crust = crust_of(f, key, std::min(radius, 0.5 * length));
    c.add(make_cylinder(radius, 0.5 * length, crust), Pose{});
    c.add(make_sphere(radius), Pose{{0, 0, 0.5 * length}, Quat{}});
    c.add(make_sphere(radius), Pose{{0, 0, -0.5 * length}, Quat{}});
  }
  return c;
}

}  // namespace

std::optional<CompositeShape> read_body_shape(const ScenarioFile& f, const std::string& key) {
  const std::string shape = f.get_choice_or(key + ".shape", "sphere",
                                            {"sphere", "box", "cross", "cylinder", "polyhedron", "composite", "hexapod",
                                             "tetrapod", "stellated_octahedron", "rod"});
  if (shape == "sphere") return std::nullopt;
  if (shape == "hexapod" || shape == "tetrapod" || shape == "stellated_octahedron" || shape == "rod")
    return read_named(f, key, shape);
  CompositeShape c;
  if (shape == "cross") {
    const double length = f.get_or<double>(key + ".length", 27e-3, io::positive);
    const double width = f.get_or<double>(key + ".width", 2e-3, io::positive);
    const double thickness = f.get_or<double>(key + ".thickness", 3e-3, io::positive);
    const double crust = f.get_or<double>(key + ".crust", 0.05 * std::min(width, thickness), io::non_negative);
    if (crust >= 0.5 * std::min({length, width, thickness}))
      f.fail(key + ".crust", "must be smaller than half the arm length, width and thickness");
    return make_huet_cross(length, width, thickness, crust);
  }
  if (shape != "composite") {
    PlacedPart part = read_convex(f, key, shape);
    c.add(std::move(part.shape), Pose{part.offset, Quat{}});
    return c;
  }
  const std::string parts = key + ".parts";
  const std::size_t n = f.array_size(parts);
  if (n == 0) f.fail(parts, "a composite needs at least one part, [[" + parts + "]]");
  for (std::size_t k = 0; k < n; ++k) {
    const std::string part_key = parts + "[" + std::to_string(k) + "]";
    const std::string part_shape = f.get_choice(part_key + ".shape", {"box", "cylinder", "sphere", "polyhedron"});
    PlacedPart part = read_convex(f, part_key, part_shape);
    const Quat q = read_orientation(f, part_key + ".orientation");
    const Vec3 position = f.get_or<Vec3>(part_key + ".position", Vec3{});
    c.add(std::move(part.shape), Pose{position + q.rotate(part.offset), q});
  }
  return c;
}

}  // namespace talus
