// A sphere on an incline (gravity tilted by theta over a flat wall): rolling without slipping
// at a = 5/7 g sin(theta) while tan(theta) <= 7/2 mu, sliding at a = g (sin - mu cos) with
// spin-up 5/2 mu g cos / R beyond; with rolling resistance, rest below atan(mu_r)
// (Huet et al. 2021, Eq. A10).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "talus/world/world.h"
#include "test_world_helpers.h"

namespace talus {
namespace {

constexpr double kG = 9.81, kRadius = 0.005, kDensity = 2500;

struct InclineRun {
  double acceleration = 0;      ///< m/s^2 along the slope, measured
  double angular_rate = 0;      ///< rad/s^2, measured spin-up
  double final_speed = 0;       ///< m/s
};

InclineRun incline(double theta_deg, double mu, double mu_r, double duration) {
  const double theta = theta_deg * std::numbers::pi / 180;
  WorldSettings s;
  s.domain = {{-10, -1, -1}, {10, 1, 1}};
  s.gravity = {kG * std::sin(theta), 0, -kG * std::cos(theta)};
  s.tangential_model = TangentialModel::memory;
  ContactParams c = testing::glass_contact(kRadius, kDensity, mu, 1.0);
  if (mu_r > 0) {
    c.rolling.enabled = true;
    c.rolling.friction = mu_r;
  }
  const double mass = kDensity * 4.0 / 3.0 * std::numbers::pi * std::pow(kRadius, 3);
  s.time_step = params::contact_time(c.normal_stiffness, mass, 0.5) / 50;
  World w(s);
  w.contacts().resize(1, 1);
  w.contacts().set_pair(0, 0, c);
  w.contacts().set_wall(0, 0, c);
  Wall floor;
  floor.normal = {0, 0, 1};
  w.add_wall(floor);
  // Start at the static overlap so the sphere does not bounce.
  const double overlap = mass * kG * std::cos(theta) / c.normal_stiffness;
  w.add_particle(testing::sphere({0, 0, kRadius - overlap}, kRadius, kDensity));

  const auto steps = static_cast<std::uint64_t>(duration / s.time_step);
  w.run(steps / 2);
  const double t1 = w.time(), v1 = w.particles().velocity[0].x, w1 = w.particles().angular_velocity[0].y;
  w.run(steps - steps / 2);
  const double t2 = w.time(), v2 = w.particles().velocity[0].x, w2 = w.particles().angular_velocity[0].y;
  return {(v2 - v1) / (t2 - t1), (w2 - w1) / (t2 - t1), norm(w.particles().velocity[0])};
}

TEST(Incline, RollsWithoutSlipping) {
  const double theta = 20, mu = 0.3;  // tan 20 = 0.36 <= 3.5 * 0.3
  const InclineRun r = incline(theta, mu, 0, 0.2);
  const double expected = 5.0 / 7.0 * kG * std::sin(theta * std::numbers::pi / 180);
  EXPECT_NEAR(r.acceleration / expected, 1.0, 0.005);
  EXPECT_NEAR(r.angular_rate * kRadius / expected, 1.0, 0.005);  // rolling: omega R = v
}

TEST(Incline, SlidesAboveTheRollingLimit) {
  const double theta = 50, mu = 0.2;  // tan 50 = 1.19 > 3.5 * 0.2
  const double t = theta * std::numbers::pi / 180;
  const InclineRun r = incline(theta, mu, 0, 0.2);
  EXPECT_NEAR(r.acceleration / (kG * (std::sin(t) - mu * std::cos(t))), 1.0, 0.005);
  EXPECT_NEAR(r.angular_rate / (2.5 * mu * kG * std::cos(t) / kRadius), 1.0, 0.005);
}

TEST(Incline, RollingResistanceHoldsBelowItsAngle) {
  const double mu_r = 0.1;  // beta = atan(0.1) = 5.71 deg
  const InclineRun held = incline(4.0, 0.5, mu_r, 0.3);
  EXPECT_LT(held.final_speed, 1e-6);
  const InclineRun rolls = incline(8.0, 0.5, mu_r, 0.3);
  EXPECT_GT(rolls.final_speed, 0.01);
}

}  // namespace
}  // namespace talus
