// A sphere declared as a one-part rigid shape follows the same trajectory through the convex-part
// narrow phase as through the analytic sphere path.
#include <gtest/gtest.h>

#include "talus/shape/convex_shape.h"
#include "talus/world/world.h"
#include "test_world_helpers.h"

namespace talus {
namespace {

std::vector<Vec3> oblique_collision(bool as_shape) {
  WorldSettings s;
  s.domain = {{-1, -1, -1}, {1, 1, 1}};
  s.gravity = {0, 0, -9.81};
  s.time_step = 2e-6;
  World w(s);
  w.contacts().resize(1, 1);
  const ContactParams c = testing::glass_contact(0.005, 2500, 0.4);
  w.contacts().set_pair(0, 0, c);
  w.contacts().set_wall(0, 0, c);
  int shape = 0;
  if (as_shape) {
    CompositeShape ball;
    ball.add(make_sphere(0.005), Pose{});
    shape = w.add_shape(ball);
  }
  ParticleInit a = testing::sphere({-0.006, 0.002, 0}, 0.005, 2500);
  a.velocity = {1, 0, 0.2};
  a.angular_velocity = {0, 30, 10};
  a.shape = shape;
  ParticleInit b = testing::sphere({0.006, -0.002, 0.001}, 0.005, 2500);
  b.velocity = {-1, 0.1, 0};
  b.shape = shape;
  w.add_particle(a);
  w.add_particle(b);
  std::vector<Vec3> track;
  for (int k = 0; k < 5000; ++k) {
    w.step();
    if (k % 50 == 0)
      for (const auto& p : w.snapshot().particles) {
        track.push_back(p.position);
        track.push_back(p.angular_velocity);
      }
  }
  EXPECT_GT(w.diagnostics().kinetic_rotational, 0.0);
  return track;
}

TEST(SphereAsShape, SameTrajectoryAsTheAnalyticPath) {
  const std::vector<Vec3> analytic = oblique_collision(false), general = oblique_collision(true);
  ASSERT_EQ(analytic.size(), general.size());
  double worst = 0;
  for (std::size_t k = 0; k < analytic.size(); ++k)
    worst = std::max(worst, norm(analytic[k] - general[k]) / std::max(1e-3, norm(analytic[k])));
  std::printf("sphere as a shape: worst relative difference %.3g\n", worst);
  EXPECT_LT(worst, 1e-8);
}

}  // namespace
}  // namespace talus
