// GJK distance (gjk.h) on its own: known distances, curved shapes, degenerate simplices,
// warm starts, and the sphere-through-GJK vs analytic sphere-sphere check.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "talus/collide/convex_contact.h"
#include "talus/collide/convex_contact_analytic.h"
#include "talus/collide/gjk.h"
#include "talus/shape/convex_shape.h"

namespace talus {
namespace {

GjkResult distance(const ConvexShape& a, const Pose& pa, const ConvexShape& b, const Pose& pb, Vec3 warm = {}) {
  GjkOptions opt;
  opt.scale = a.bounding_radius + b.bounding_radius;
  opt.warm_direction = warm;
  return gjk_distance(PosedSupport{&a.geometry, pa, 0.0}, PosedSupport{&b.geometry, pb, 0.0}, opt);
}

TEST(GjkDistance, BoxesFaceEdgeVertex) {
  const ConvexShape box = make_box({1, 1, 1});
  EXPECT_NEAR(distance(box, Pose{}, box, Pose{{3.5, 0, 0}, {}}).distance, 1.5, 1e-12);
  // Corner-to-corner along the diagonal.
  const GjkResult r = distance(box, Pose{}, box, Pose{{3, 3, 3}, {}});
  EXPECT_NEAR(r.distance, std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(r.point_a.x, 1, 1e-12);
  EXPECT_NEAR(r.point_b.y, 2, 1e-12);
  // Edge-to-face: B rotated 45 deg about z, its edge facing A's +x face.
  const Pose pb{{1 + std::sqrt(2.0) + 0.25, 0.3, 0}, Quat::from_axis_angle({0, 0, 1}, std::numbers::pi / 4)};
  EXPECT_NEAR(distance(box, Pose{}, box, pb).distance, 0.25, 1e-12);
  EXPECT_TRUE(distance(box, Pose{}, box, Pose{{1.5, 0.5, 0}, {}}).intersecting);
}

TEST(GjkDistance, CylindersAndSpheres) {
  const ConvexShape c = make_cylinder(0.5, 1);
  const ConvexShape s = make_sphere(0.3);
  // Side by side (curved rims): centre distance - 2 radii.
  EXPECT_NEAR(distance(c, Pose{}, c, Pose{{2, 0.1, 0.2}, {}}).distance, std::hypot(2, 0.1) - 1, 1e-9);
  // Sphere off the rim: nearest point is the rim circle.
  const double dr = std::hypot(1.5 - 0.5, 1.6 - 1.0) - 0.3;
  EXPECT_NEAR(distance(c, Pose{}, s, Pose{{1.5, 0, 1.6}, {}}).distance, dr, 1e-9);
}

TEST(GjkDistance, DegenerateSimplicesNoNaN) {
  const ConvexShape box = make_box({1, 1, 1});
  // Parallel faces exactly aligned: many equal supports, collinear/coplanar simplices.
  for (double gap : {0.0, 1e-12, 1e-6, 0.5}) {
    const GjkResult r = distance(box, Pose{}, box, Pose{{0, 0, 2 + gap}, {}});
    EXPECT_TRUE(std::isfinite(r.distance) && std::isfinite(r.point_a.x));
    if (!r.intersecting) EXPECT_NEAR(r.distance, gap, 1e-10);
  }
}

TEST(GjkDistance, WarmStartSavesIterations) {
  const ConvexShape a = make_polyhedron({{1, 0, 0}, {-1, 0.2, 0}, {0, 1, 0.1}, {0, -1, 0}, {0.1, 0, 1}, {0, 0, -1},
                                         {0.6, 0.6, 0.6}, {-0.6, -0.5, 0.6}});
  int cold = 0, warm = 0;
  Vec3 sep;
  for (int step = 0; step < 200; ++step) {
    const double t = step * 0.01;
    const Pose pa{{}, Quat::from_axis_angle({0, 0, 1}, 0.3 * t)};
    const Pose pb{{2.5 + 0.2 * std::sin(t), 0.3 * t, 0.1}, Quat::from_axis_angle({1, 1, 0}, t)};
    cold += distance(a, pa, a, pb).iterations;
    const GjkResult r = distance(a, pa, a, pb, sep);
    warm += r.iterations;
    sep = r.separation;
    EXPECT_NEAR(r.distance, distance(a, pa, a, pb).distance, 1e-10);
  }
  std::printf("GJK iterations per query: cold %.2f, warm %.2f\n", cold / 200.0, warm / 200.0);
  EXPECT_LT(warm, cold);
}

// Brief (a): a sphere as a general convex shape through GJK (point core + crust = radius, and a
// sphere core with a thinner crust) gives the analytic sphere-sphere answer to 1e-8 relative.
TEST(GjkSphere, CrustMatchesAnalyticSphereSphere) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 200; ++trial) {
    const double ra = 0.5 + 0.4 * u(rng), rb = 0.5 + 0.4 * u(rng);
    const Vec3 ca{u(rng), u(rng), u(rng)};
    const Vec3 cb = ca + normalized_or_zero({u(rng), u(rng), u(rng)}) * ((ra + rb) * (0.6 + 0.39 * u(rng)));
    const PartContact ref = sphere_sphere_contact(ra, ca, rb, cb);
    // Sphere core of radius r - c rounded by c: a curved core, not a point.
    ConvexShape sa{Sphere{ra}, Sphere{ra * 0.8}, ra * 0.2, ra}, sb{Sphere{rb}, Sphere{rb * 0.7}, rb * 0.3, rb};
    for (const auto& [a, b] : {std::pair{make_sphere(ra), make_sphere(rb)}, std::pair{sa, sb}}) {
      // Curved cores must not intersect here: beyond the crust EPA answers (to ~1e-4 on spheres).
      if (a.crust + b.crust < ref.delta_n) continue;
      const PartContact g = crust_contact(a, Pose{ca, {}}, b, Pose{cb, {}});
      ASSERT_TRUE(g.touching);
      EXPECT_NEAR(g.delta_n, ref.delta_n, 1e-8 * ref.delta_n);
      EXPECT_NEAR(norm(g.normal - ref.normal), 0, 1e-8);
      EXPECT_NEAR(norm(g.point - ref.point), 0, 1e-8 * ref.delta_n);
    }
  }
}

}  // namespace
}  // namespace talus
