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
  const MassProperties quad = mass_properties(rotated, 770);
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
  const MassProperties mp = mass_properties(c, 1);
  // Error in the lens (the only approximated part) below 1e-4 of the lens at the default grid.
  EXPECT_NEAR(mp.volume, exact, 1e-4 * lens);
  EXPECT_NEAR(norm(mp.centre_of_mass), 0, 1e-12);
  std::printf("sphere lens: relative error of the overlap %.2e\n", (mp.volume - exact) / lens);
}

}  // namespace
}  // namespace talus
