#include "talus/shape/named_shapes.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace talus {

namespace {

// The rotation taking z onto the unit vector `d`.
Quat z_onto(const Vec3& d) {
  const Vec3 z{0, 0, 1};
  const Vec3 axis = cross(z, d);
  const double s = norm(axis), c = dot(z, d);
  if (s < 1e-12) return c > 0 ? Quat{} : Quat::from_axis_angle({1, 0, 0}, std::numbers::pi);
  return Quat::from_axis_angle(axis / s, std::atan2(s, c));
}

}  // namespace

double hexapod_smallest_half(double width) { return 0.5 * width; }

CompositeShape make_hexapod(double length, double width, double crust) {
  const Vec3 h{0.5 * width, 0.5 * width, 0.5 * length};
  CompositeShape c;
  c.add(make_box(h, crust), Pose{});
  c.add(make_box(h, crust), Pose{{}, Quat::from_axis_angle({1, 0, 0}, 0.5 * std::numbers::pi)});
  c.add(make_box(h, crust), Pose{{}, Quat::from_axis_angle({0, 1, 0}, 0.5 * std::numbers::pi)});
  return c;
}

double tetrapod_smallest_half(double arm, double radius) { return std::min(radius, 0.5 * arm); }

// Arms at the tetrahedral angle (cos = -1/3) meet each other within r cot(theta/2) = r/sqrt(2)
// of the centre; starting at 3r/4 they are apart, and a hub ball through their inner rims
// (radius sqrt(s^2 + r^2) = 5r/4) closes the centre. The hub meets each arm in a spherical cap
// and the arms meet nothing else, so the mass properties are exact (part_intersection.h).
double tetrapod_arm_start(double radius) { return 0.75 * radius; }
double tetrapod_hub_radius(double radius) { return 1.25 * radius; }

CompositeShape make_tetrapod(double arm, double radius, double crust) {
  const double start = tetrapod_arm_start(radius);
  if (!(arm > tetrapod_hub_radius(radius)))
    throw std::invalid_argument("a tetrapod's arms must reach past its hub: length > 1.25 radius");
  CompositeShape c;
  c.add(make_sphere(tetrapod_hub_radius(radius)), Pose{});
  for (const Vec3& corner : {Vec3{1, 1, 1}, Vec3{1, -1, -1}, Vec3{-1, 1, -1}, Vec3{-1, -1, 1}}) {
    const Vec3 d = corner / std::sqrt(3.0);
    c.add(make_cylinder(radius, 0.5 * (arm - start), crust), Pose{0.5 * (arm + start) * d, z_onto(d)});
  }
  return c;
}

// A regular tetrahedron's inradius: a third of the cube's half side.
double stellated_octahedron_smallest_half(double size) { return 0.5 * size / 3; }

CompositeShape make_stellated_octahedron(double size, double crust) {
  const double a = 0.5 * size;  // the cube's half side
  const std::vector<Vec3> first{{a, a, a}, {a, -a, -a}, {-a, a, -a}, {-a, -a, a}};
  std::vector<Vec3> second;
  for (const Vec3& v : first) second.push_back(-1.0 * v);
  CompositeShape c;
  c.add(make_polyhedron(first, crust), Pose{});
  c.add(make_polyhedron(second, crust), Pose{});
  return c;
}

double rod_smallest_half(double length, double radius) { return std::min(radius, 0.5 * length); }

CompositeShape make_rod(double length, double radius, double crust) {
  CompositeShape c;
  c.add(make_cylinder(radius, 0.5 * length, crust), Pose{});
  c.add(make_sphere(radius), Pose{{0, 0, 0.5 * length}, Quat{}});
  c.add(make_sphere(radius), Pose{{0, 0, -0.5 * length}, Quat{}});
  return c;
}

}  // namespace talus
