// Convex shapes, hulls and mass properties: analytic solids to 1e-12, the Huet et al. (2021)
// cross (V = 0.312 cm^3) against an independent inclusion-exclusion, and the overlap quadrature.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "talus/shape/composite_shape.h"
#include "talus/shape/convex_hull.h"
#include "talus/shape/convex_shape.h"
#include "talus/shape/mass_properties.h"

namespace talus {
namespace {

constexpr double kPi = std::numbers::pi;

void expect_rel(double got, double want, double tol) { EXPECT_NEAR(got, want, tol * std::abs(want)) << want; }

std::vector<Vec3> box_corners(const Vec3& h) {
  std::vector<Vec3> v;
  for (int k = 0; k < 8; ++k) v.push_back({k & 1 ? h.x : -h.x, k & 2 ? h.y : -h.y, k & 4 ? h.z : -h.z});
  return v;
}

TEST(ShapeHull, CubeHasSixQuadFaces) {
  auto pts = box_corners({1, 2, 3});
  pts.push_back({0, 0, 0});       // interior
  pts.push_back({1, 0, 0});       // on a face
  const ConvexHull h = build_convex_hull(pts);
  EXPECT_EQ(h.vertices.size(), 8u);
  EXPECT_EQ(h.triangles.size(), 12u);
  ASSERT_EQ(h.faces.size(), 6u);
  for (const HullFace& f : h.faces) {
    EXPECT_EQ(f.vertices.size(), 4u);
    EXPECT_NEAR(norm(f.normal), 1, 1e-14);
  }
}

TEST(ShapeHull, RandomCloudContainsAllPoints) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> g;
  std::vector<Vec3> pts;
  for (int i = 0; i < 300; ++i) pts.push_back({g(rng), g(rng), 0.5 * g(rng)});
  const ConvexHull h = build_convex_hull(pts);
  // Euler: V - E + F = 2 on the triangulation (E = 3F/2).
  EXPECT_EQ(static_cast<int>(h.vertices.size()) - static_cast<int>(h.triangles.size()) / 2, 2);
  for (const Vec3& p : pts)
    for (const HullFace& f : h.faces) EXPECT_LE(dot(f.normal, p) - f.offset, 1e-9);
}

TEST(ShapeHull, DegenerateThrows) {
  EXPECT_THROW(build_convex_hull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}), std::invalid_argument);
}

TEST(ShapeConvex, SupportAndAabb) {
  const ConvexShape b = make_box({1, 2, 3}, 0.5);
  const Vec3 s = support(b, {1, 1, 1});
  EXPECT_NEAR(s.x, 0.5 + 0.5 / std::sqrt(3), 1e-15);
  const Pose p{{10, 0, 0}, Quat::from_axis_angle({0, 0, 1}, kPi / 2)};
  const Aabb a = aabb(b, p);
  EXPECT_NEAR(a.hi.x, 12, 1e-12);  // y extent becomes x extent
  EXPECT_NEAR(a.lo.y, -1, 1e-12);
  const ConvexShape c = make_cylinder(1, 2, 0.1);
  EXPECT_NEAR(support(c, {0, 0, -1}).z, -2, 1e-15);
  EXPECT_NEAR(support(c, {3, 4, 0}).x, 0.6, 1e-15);
}

TEST(ShapeConvex, PolyhedronErosionOfCubeIsTheBoxCore) {
  const ConvexShape p = make_polyhedron(box_corners({1, 2, 3}), 0.25);
  const auto& core = std::get<ConvexPolyhedron>(p.core).hull;
  ASSERT_EQ(core.vertices.size(), 8u);
  for (const Vec3& v : core.vertices) {
    EXPECT_NEAR(std::abs(v.x), 0.75, 1e-12);
    EXPECT_NEAR(std::abs(v.y), 1.75, 1e-12);
    EXPECT_NEAR(std::abs(v.z), 2.75, 1e-12);
  }
  // A contact-shape face of an eroded octahedron stays on the nominal face plane.
  const ConvexShape oct = make_polyhedron({{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}, 0.1);
  const Vec3 n = normalized_or_zero({1, 1, 1});
  EXPECT_NEAR(dot(support(oct, n), n), 1 / std::sqrt(3.0), 1e-12);
}

TEST(MassProperties, SphereBoxCylinderAnalytic) {
  const double rho = 770;
  const MassProperties s = mass_properties(make_sphere(0.3), rho);
  const double ms = rho * 4.0 / 3 * kPi * 0.027;
  expect_rel(s.mass, ms, 1e-12);
  for (int k = 0; k < 3; ++k) expect_rel(s.inertia(k, k), 0.4 * ms * 0.09, 1e-12);

  const MassProperties b = mass_properties(make_box({0.5, 1, 1.5}, 0.1), rho);
  const double mb = rho * 6;
  expect_rel(b.mass, mb, 1e-12);
  expect_rel(b.inertia(0, 0), mb * (4 + 9) / 12, 1e-12);
  expect_rel(b.inertia(1, 1), mb * (1 + 9) / 12, 1e-12);
  expect_rel(b.inertia(2, 2), mb * (1 + 4) / 12, 1e-12);
  EXPECT_NEAR(b.inertia(0, 1), 0, 1e-15);

  const MassProperties c = mass_properties(make_cylinder(0.2, 0.5), rho);
  const double mc = rho * kPi * 0.04 * 1.0;
  expect_rel(c.mass, mc, 1e-12);
  expect_rel(c.inertia(2, 2), mc * 0.04 / 2, 1e-12);
  expect_rel(c.inertia(0, 0), mc * (3 * 0.04 + 1.0) / 12, 1e-12);
}

TEST(MassProperties, PolyhedronBoxMatchesBox) {
  const MassProperties p = mass_properties(make_polyhedron(box_corners({0.5, 1, 1.5})), 2);
  const MassProperties b = mass_properties(make_box({0.5, 1, 1.5}), 2);
  expect_rel(p.volume, b.volume, 1e-12);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(p.inertia(i, j), b.inertia(i, j), 1e-12 * b.inertia(0, 0));
}

TEST(MassProperties, PrincipalFrameOfOffsetRotatedBox) {
  CompositeShape c;
  const Quat q = Quat::from_axis_angle({1, 2, 3}, 0.7);
  c.add(make_box({0.5, 1, 1.5}), Pose{{1, 2, 3}, q});
  const MassProperties mp = mass_properties(c, 1, {.force_quadrature = true});  // single part: exact
  EXPECT_NEAR(mp.centre_of_mass.y, 2, 1e-12);
  const double m = 6;
  EXPECT_NEAR(mp.principal_moments.x, m * 5 / 12, 1e-12);
  EXPECT_NEAR(mp.principal_moments.z, m * 13 / 12, 1e-12);
  // The smallest principal axis is the box's long (z) axis.
  const Vec3 axis = mp.principal_orientation.rotate({1, 0, 0});
  EXPECT_NEAR(std::abs(dot(axis, q.rotate({0, 0, 1}))), 1, 1e-12);
  const CompositeShape pc = to_principal_frame(c, mp);
  const MassProperties again = mass_properties(pc, 1, {.force_quadrature = true});
  EXPECT_NEAR(norm(again.centre_of_mass), 0, 1e-12);
  EXPECT_NEAR(again.inertia(0, 1), 0, 1e-12);
  EXPECT_NEAR(again.inertia(0, 0), m * 5 / 12, 1e-12);
}

// Huet et al. 2021 Sec. III B: 27 x 2 x 3 mm arms, V = 0.312 cm^3, rho = 770 kg/m^3.
TEST(MassProperties, HuetCrossExact) {
  const double L = 27e-3, W = 2e-3, H = 3e-3, rho = 770;
  const MassProperties mp = mass_properties(make_huet_cross(), rho);
  expect_rel(mp.volume, 0.312e-6, 1e-12);
  expect_rel(mp.mass, 770 * 0.312e-6, 1e-12);
  EXPECT_NEAR(norm(mp.centre_of_mass), 0, 1e-18);
  // Independent: arm along x + arm along y - shared W x W x H block.
  const double ma = rho * L * W * H, mc = rho * W * W * H;
  const double ixx = ma * (W * W + H * H) / 12 + ma * (L * L + H * H) / 12 - mc * (W * W + H * H) / 12;
  const double izz = 2 * ma * (L * L + W * W) / 12 - mc * (2 * W * W) / 12;
  expect_rel(mp.inertia(0, 0), ixx, 1e-12);
  expect_rel(mp.inertia(1, 1), ixx, 1e-12);
  expect_rel(mp.inertia(2, 2), izz, 1e-12);
  EXPECT_NEAR(mp.inertia(0, 1), 0, 1e-12 * izz);
  expect_rel(mp.principal_moments.z, izz, 1e-12);
}

TEST(MassProperties, QuadratureOnRotatedCross) {
  // Rotated in its plane, the arms are no longer body-axis aligned: the quadrature path runs.
  const Quat q = Quat::from_axis_angle({0, 0, 1}, 0.5);
  CompositeShape rotated;
  for (const CompositePart& p : make_huet_cross().parts) rotated.add(p.shape, Pose{{}, q} * p.pose);
  const MassProperties exact = mass_properties(make_huet_cross(), 770);
  const MassProperties quad = mass_properties(rotated, 770, {.force_quadrature = true});
  const double overlap_fraction = 12.0 / 312.0;
  EXPECT_NEAR(quad.volume, exact.volume, 2e-3 * overlap_fraction * exact.volume);  // 0.2 % of the overlap
  std::printf("rotated cross: volume rel err %.2e, Izz rel err %.2e\n", quad.volume / exact.volume - 1,
              quad.principal_moments.z / exact.principal_moments.z - 1);
  for (int k = 0; k < 3; ++k) expect_rel(quad.principal_moments[k], exact.principal_moments[k], 1e-5);
}

TEST(MassProperties, QuadratureOnOverlappingSpheres) {
  const double R = 1, d = 1.2;
  CompositeShape c;
  c.add(make_sphere(R), Pose{{-d / 2, 0, 0}, {}});
  c.add(make_sphere(R), Pose{{d / 2, 0, 0}, {}});
  const double lens = kPi * (4 * R + d) * (2 * R - d) * (2 * R - d) / 12;
  const double exact = 2 * 4.0 / 3 * kPi - lens;
  const MassProperties mp = mass_properties(c, 1, {.force_quadrature = true});
  // Error in the lens (the only approximated part) below 1e-4 of the lens at the default grid.
  EXPECT_NEAR(mp.volume, exact, 1e-4 * lens);
  EXPECT_NEAR(norm(mp.centre_of_mass), 0, 1e-12);
  std::printf("sphere lens: relative error of the overlap %.2e\n", (mp.volume - exact) / lens);
}

// Inclusion-exclusion with half-space intersections: the cross turned off the body axes (pair
// overlaps) and a hexapod turned anyhow (three arms meeting in one cube) keep their exact
// axis-aligned mass properties to round-off.
TEST(MassProperties, TurnedCompositesOfBoxesStayExact) {
  const Quat turn = Quat::from_axis_angle(normalized_or_zero(Vec3{0.3, -0.5, 0.8}), 0.7);
  const Vec3 shift{1e-3, -2e-3, 0.5e-3};
  auto turned = [&](const CompositeShape& c) {
    CompositeShape out;
    for (const CompositePart& p : c.parts) out.add(p.shape, Pose{shift, turn} * p.pose);
    return out;
  };
  const double arm = 20e-3, width = 2e-3;
  CompositeShape hexapod;
  const Vec3 h{0.5 * width, 0.5 * width, 0.5 * arm};
  hexapod.add(make_box(h), Pose{});
  hexapod.add(make_box(h), Pose{{}, Quat::from_axis_angle({1, 0, 0}, 0.5 * kPi)});
  hexapod.add(make_box(h), Pose{{}, Quat::from_axis_angle({0, 1, 0}, 0.5 * kPi)});
  expect_rel(mass_properties(hexapod, 1).volume, 3 * arm * width * width - 2 * width * width * width, 1e-12);
  for (const CompositeShape& aligned : {make_huet_cross(), hexapod}) {
    const MassProperties want = mass_properties(aligned, 770), got = mass_properties(turned(aligned), 770);
    expect_rel(got.volume, want.volume, 1e-12);
    for (int k = 0; k < 3; ++k) {
      expect_rel(got.principal_moments[k], want.principal_moments[k], 1e-11);
      EXPECT_NEAR(got.centre_of_mass[k], shift[k], 1e-12 * arm);
    }
  }
}

// Two regular tetrahedra in the corners of one cube of half side a meet in the octahedron
// |x| + |y| + |z| <= a: V = 2 (8/3) a^3 - (4/3) a^3 = 4 a^3 and, from the tetrahedra's and the
// octahedron's int x^2 dV (V_t a^2 / 5 and 2 a^5 / 15), I = 2 rho (2 (8/15) - 2/15) a^5.
TEST(MassProperties, StellatedOctahedronExact) {
  const double a = 1.5e-3, rho = 2500;
  const std::vector<Vec3> first{{a, a, a}, {a, -a, -a}, {-a, a, -a}, {-a, -a, a}};
  std::vector<Vec3> second;
  for (const Vec3& v : first) second.push_back(-1.0 * v);
  CompositeShape star;
  star.add(make_polyhedron(first), Pose{});
  star.add(make_polyhedron(second), Pose{});
  const MassProperties mp = mass_properties(star, rho);
  expect_rel(mp.volume, 4 * a * a * a, 1e-12);
  for (int k = 0; k < 3; ++k) expect_rel(mp.principal_moments[k], rho * 28.0 / 15.0 * std::pow(a, 5), 1e-12);
  EXPECT_NEAR(norm(mp.centre_of_mass), 0, 1e-15);
}

// A spherocylinder as a cylinder and two balls on its caps: V = pi r^2 L + 4/3 pi r^3; each half
// ball (mass m_h, centroid 3r/8 beyond its cap) adds 2/5 m_h r^2 + m_h (L^2/4 + 3 r L / 8) across.
TEST(MassProperties, RodExact) {
  const double r = 1e-3, L = 6e-3, rho = 1000;
  CompositeShape rod;
  rod.add(make_cylinder(r, 0.5 * L), Pose{});
  rod.add(make_sphere(r), Pose{{0, 0, 0.5 * L}, {}});
  rod.add(make_sphere(r), Pose{{0, 0, -0.5 * L}, {}});
  const MassProperties mp = mass_properties(rod, rho);
  const double mc = rho * kPi * r * r * L, mh = rho * 2.0 / 3.0 * kPi * r * r * r;
  expect_rel(mp.volume, kPi * r * r * L + 4.0 / 3.0 * kPi * r * r * r, 1e-12);
  const double across = mc * (3 * r * r + L * L) / 12 + 2 * (0.4 * mh * r * r + mh * (L * L / 4 + 3 * r * L / 8));
  const double along = mc * r * r / 2 + 2 * 0.4 * mh * r * r;
  expect_rel(mp.principal_moments.x, along, 1e-12);
  expect_rel(mp.principal_moments.y, across, 1e-12);
  expect_rel(mp.principal_moments.z, across, 1e-12);
}

// Two balls meeting in a lens: exact volume; the quadrature agrees on the inertia.
TEST(MassProperties, OverlappingSpheresExact) {
  const double R = 1, d = 1.2;
  CompositeShape c;
  c.add(make_sphere(R), Pose{{-d / 2, 0.2, 0}, {}});
  c.add(make_sphere(R), Pose{{d / 2, 0.2, 0}, {}});
  const double lens = kPi * (4 * R + d) * (2 * R - d) * (2 * R - d) / 12;
  const MassProperties exact = mass_properties(c, 1);
  expect_rel(exact.volume, 2 * 4.0 / 3 * kPi - lens, 1e-12);
  EXPECT_NEAR(exact.centre_of_mass.y, 0.2, 1e-12);
  const MassProperties quad = mass_properties(c, 1, {.force_quadrature = true});
  for (int k = 0; k < 3; ++k) expect_rel(exact.principal_moments[k], quad.principal_moments[k], 1e-4);
}

// Crossing cylinders have no closed form here: the quadrature runs, within its bound.
TEST(MassProperties, CrossingCylindersFallBackToQuadrature) {
  const double r = 1, h = 4;
  CompositeShape c;
  c.add(make_cylinder(r, h), Pose{});
  c.add(make_cylinder(r, h), Pose{{}, Quat::from_axis_angle({1, 0, 0}, 0.5 * kPi)});
  const double steinmetz = 16.0 / 3.0 * r * r * r;  // two perpendicular unit cylinders share 16/3 r^3
  const MassProperties mp = mass_properties(c, 1);
  EXPECT_NEAR(mp.volume, 2 * 2 * kPi * r * r * h - steinmetz, 1e-3 * steinmetz);
}

}  // namespace
}  // namespace talus
