// Non-spherical bodies in motion: a box on an incline (stick below atan(mu), slide above with
// a = g (sin - mu cos)) and two crosses thrown at each other (deterministic, no energy created).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "talus/contact/parameter_procedure.h"
#include "talus/scenario/rigid_body_type.h"
#include "talus/shape/convex_shape.h"
#include "talus/world/world.h"

namespace talus {
namespace {

constexpr double kG = 9.81;

ContactParams block_contact(double mass, double friction) {
  ContactParams c;
  c.normal_stiffness = 1e4;
  c.normal_damping.coefficient = params::normal_damping(c.normal_stiffness, mass, 0.3);
  c.tangential_stiffness = 2.0 / 7.0 * c.normal_stiffness;
  c.tangential_damping = c.normal_damping;
  c.friction = friction;
  return c;
}

// Speed along the slope after `duration`, and the acceleration over its second half.
std::pair<double, double> box_on_incline(double theta_deg, double mu, bool manifold, double duration) {
  const double theta = theta_deg * std::numbers::pi / 180;
  CompositeShape box;
  box.add(make_box({0.01, 0.005, 0.0025}, 2e-4), Pose{});
  const RigidBodyType type = make_rigid_body_type(box, 1000);
  WorldSettings s;
  s.domain = {{-5, -1, -1}, {5, 1, 1}};
  s.gravity = {kG * std::sin(theta), 0, -kG * std::cos(theta)};
  s.contact_manifold = manifold;
  const ContactParams c = block_contact(type.mass, mu);
  s.time_step = params::contact_time(c.normal_stiffness, type.mass / 4, 0.3) / 50;
  World w(s);
  w.contacts().resize(1, 1);
  w.contacts().set_pair(0, 0, c);
  w.contacts().set_wall(0, 0, c);
  Wall floor;
  floor.normal = {0, 0, 1};
  w.add_wall(floor);
  const int index = w.add_shape(type.shape);
  // The principal frame of a box is its own frame up to a permutation of axes: find the
  // orientation that puts the 5 mm thickness vertical by trying the principal axes.
  w.add_particle(rigid_particle(type, index, {0, 0, 0.0025 - type.mass * kG * std::cos(theta) / c.normal_stiffness}, Quat{}, 0));
  const auto steps = static_cast<std::uint64_t>(duration / s.time_step);
  w.run(steps / 2);
  const double v1 = w.particles().velocity[0].x, t1 = w.time();
  w.run(steps - steps / 2);
  const double v2 = w.particles().velocity[0].x, t2 = w.time();
  return {v2, (v2 - v1) / (t2 - t1)};
}

TEST(RigidDynamics, BoxOnInclineSticksBelowFrictionAngle) {
  // atan(0.5) = 26.6 deg
  const auto [speed, acceleration] = box_on_incline(20, 0.5, true, 0.3);
  std::printf("box at 20 deg: speed %.3g m/s\n", speed);
  EXPECT_LT(std::abs(speed), 1e-6);
}

TEST(RigidDynamics, BoxOnInclineSlidesAboveFrictionAngle) {
  const double theta = 35 * std::numbers::pi / 180, mu = 0.5;
  for (bool manifold : {true, false}) {
    const auto [speed, acceleration] = box_on_incline(35, mu, manifold, 0.3);
    const double expected = kG * (std::sin(theta) - mu * std::cos(theta));
    std::printf("box at 35 deg, %s: a / a_expected - 1 = %.3g\n", manifold ? "manifold" : "one point", acceleration / expected - 1);
    EXPECT_NEAR(acceleration / expected, 1.0, 0.005);
  }
}

struct ThrowResult {
  std::vector<Vec3> positions;
  double worst_growth = 0;  ///< max (E(t) - E(0)) / E_kin(0)
  double kinetic_left = 0;  ///< E_kin(end) / E_kin(0)
};

ThrowResult throw_crosses(bool manifold, bool gjk_warm_start = true) {
  const RigidBodyType type = make_rigid_body_type(make_huet_cross(27e-3, 2e-3, 3e-3, 1e-4), 770);
  WorldSettings s;
  s.domain = {{-1, -1, -1}, {1, 1, 1}};
  s.gravity = {};
  s.contact_manifold = manifold;
  s.gjk_warm_start = gjk_warm_start;
  // Table I normal parameters (Huet et al. 2021), k_t = 2/7 k_n and no tangential damping:
  // with Table I's k_t = 300 N/m and gamma_t = 1e3 1/s, the saturated reset of Eq. (8) stores
  // -eta_t v_t / k_t in the spring, which the elastic energy then counts (see the closing note).
  ContactParams c;
  c.normal_stiffness = 4.5e5;
  c.normal_damping.coefficient = params::normal_damping(c.normal_stiffness, type.mass / 2, 0.85);
  c.tangential_stiffness = 2.0 / 7.0 * c.normal_stiffness;
  c.friction = 0.46;
  s.time_step = 2.5e-6;
  World w(s);
  w.contacts().resize(1, 1);
  w.contacts().set_pair(0, 0, c);
  w.contacts().set_wall(0, 0, c);
  const int index = w.add_shape(type.shape);
  ParticleInit a = rigid_particle(type, index, {-0.02, 0.003, 0}, Quat::from_axis_angle({1, 1, 0}, 0.4), 0);
  a.velocity = {1, 0, 0};
  a.angular_velocity = {0, 0, 20};
  ParticleInit b = rigid_particle(type, index, {0.02, -0.003, 0.001}, Quat::from_axis_angle({0, 1, 1}, 1.1), 0);
  b.velocity = {-1, 0, 0};
  w.add_particle(a);
  w.add_particle(b);
  ThrowResult r;
  double e0 = -1, k0 = 0;
  for (int k = 0; k < 16000; ++k) {
    w.step();
    const Diagnostics d = w.diagnostics();
    const double e = d.kinetic() + d.elastic();
    if (e0 < 0) e0 = e, k0 = d.kinetic();
    r.worst_growth = std::max(r.worst_growth, (e - e0) / k0);
  }
  r.kinetic_left = w.diagnostics().kinetic() / k0;
  for (const auto& p : w.snapshot().particles) r.positions.push_back(p.position);
  return r;
}

// One point per part pair with GJK warm-started (the default) and cold, and the manifold. The
// arms meet crossed, never face on face, so the warm start's witness points are the cold start's
// and the two one-point runs agree to GJK's tolerance.
TEST(RigidDynamics, CrossesCollideDeterministicallyWithoutCreatingEnergy) {
  struct Case {
    bool manifold, warm;
    const char* name;
  };
  std::vector<ThrowResult> one_point;
  for (const Case& k : {Case{false, true, "one point"}, Case{false, false, "one point, GJK cold"}, Case{true, true, "manifold"}}) {
    const ThrowResult one = throw_crosses(k.manifold, k.warm), two = throw_crosses(k.manifold, k.warm);
    std::printf("crosses, %s: worst energy growth %.3g of E_kin(0), E_kin left %.9f\n", k.name, one.worst_growth, one.kinetic_left);
    EXPECT_LT(one.worst_growth, 1e-6);
    EXPECT_LT(one.kinetic_left, 0.999);  // they did collide, and lost energy
    ASSERT_EQ(one.positions.size(), two.positions.size());
    for (std::size_t i = 0; i < one.positions.size(); ++i) EXPECT_EQ(one.positions[i], two.positions[i]);
    if (!k.manifold) one_point.push_back(one);
  }
  const ThrowResult &warm = one_point[0], &cold = one_point[1];
  EXPECT_NEAR(warm.kinetic_left, cold.kinetic_left, 1e-9);
  for (std::size_t i = 0; i < warm.positions.size(); ++i) EXPECT_LT(norm(warm.positions[i] - cold.positions[i]), 1e-9);
}

}  // namespace
}  // namespace talus
