#include "talus/scenario/shape_reader.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "talus/io/number_format.h"
#include "talus/scenario/mesh_shape_reader.h"
#include "talus/shape/convex_hull.h"
#include "talus/shape/named_shapes.h"

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

// Named shapes of the granular literature, as composites of convex parts (named_shapes.h).
CompositeShape read_named(const ScenarioFile& f, const std::string& key, const std::string& shape) {
  if (shape == "hexapod") {
    const double length = f.get<double>(key + ".length", io::positive), width = f.get<double>(key + ".width", io::positive);
    if (width >= length) f.fail(key + ".width", "must be smaller than the length");
    return make_hexapod(length, width, crust_of(f, key, hexapod_smallest_half(width)));
  }
  if (shape == "tetrapod") {
    const double arm = f.get<double>(key + ".length", io::positive), radius = f.get<double>(key + ".radius", io::positive);
    if (!(arm > 1.25 * radius)) f.fail(key + ".radius", "must be below 0.8 of the arm length: the arms reach past the hub of radius 1.25 radius");
    return make_tetrapod(arm, radius, crust_of(f, key, tetrapod_smallest_half(arm, radius)));
  }
  if (shape == "stellated_octahedron") {
    const double size = f.get<double>(key + ".size", io::positive);
    return make_stellated_octahedron(size, crust_of(f, key, stellated_octahedron_smallest_half(size)));
  }
  const double length = f.get<double>(key + ".length", io::positive), radius = f.get<double>(key + ".radius", io::positive);
  return make_rod(length, radius, crust_of(f, key, rod_smallest_half(length, radius)));
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
