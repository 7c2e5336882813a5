// Sleeping pairs of rigid bodies (world/pair_budgets.h, ShapedContacts::BlockWake): a pair found
// apart is not tested again until the bodies' travels could have closed its gap, and a row whose
// sleepers were all far from waking is served from its last pass's awake entries. Both must be
// conservative: a run with them gives the run in which every pair is tested every step (a list
// rebuilt each step, which clears budgets and rows), for bodies that approach and collide while
// another body far away makes the travel clock run fast.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "talus/contact/parameter_procedure.h"
#include "talus/scenario/rigid_body_type.h"
#include "talus/shape/convex_shape.h"
#include "talus/world/composite_stats.h"
#include "talus/world/world.h"

namespace talus {
namespace {


// Five 1 cm cubes at rest 1.5 cm apart along x, a sixth thrown at the first along x (a cradle),
// and a seventh far away flying along y three times as fast, so that the travel clock runs ahead of
// every body in the line.
std::unique_ptr<World> cube_line(double skin, int steps, bool manifold = true) {
  WorldSettings s;
  s.domain = {{-1, -1, -1}, {1, 1, 1}};
  s.gravity = {};
  s.contact_manifold = manifold;
  s.skin = skin;
  CompositeShape cube;
  cube.add(make_box({0.005, 0.005, 0.005}, 2e-4), Pose{});
  const RigidBodyType c = make_rigid_body_type(cube, 1000);
  ContactParams k;
  k.normal_stiffness = 1e4;
  k.normal_damping.coefficient = params::normal_damping(k.normal_stiffness, c.mass, 0.9);
  k.tangential_stiffness = 2.0 / 7.0 * k.normal_stiffness;
  k.tangential_damping = k.normal_damping;
  k.friction = 0.5;
  s.time_step = params::contact_time(k.normal_stiffness, c.mass / 4, 0.9) / 50;
  auto w = std::make_unique<World>(s);
  w->contacts().resize(1, 1);
  w->contacts().set_pair(0, 0, k);
  w->contacts().set_wall(0, 0, k);
  const int shape = w->add_shape(cube);
  for (int n = 0; n < 5; ++n) w->add_particle(rigid_particle(c, shape, {0.015 * n, 0, 0}, Quat{}, 0));
  ParticleInit thrown = rigid_particle(c, shape, {-0.02, 0.001, 0.0005}, Quat::from_axis_angle({0, 0, 1}, 0.05), 0);
  thrown.velocity = {0.2, 0, 0};
  w->add_particle(thrown);
  ParticleInit far = rigid_particle(c, shape, {0.5, -0.5, 0.5}, Quat{}, 0);
  far.velocity = {0, 0.6, 0};
  w->add_particle(far);
  w->run(steps);
  return w;
}

void expect_same_run(const World& sleeping, const World& every_step, int steps) {
  const ParticleStore& a = sleeping.particles();
  const ParticleStore& b = every_step.particles();
  ASSERT_EQ(a.owned, b.owned);
  ASSERT_GT(every_step.rebuilds(), static_cast<std::uint64_t>(steps / 2)) << "the reference must rebuild";
  ASSERT_LT(sleeping.rebuilds(), static_cast<std::uint64_t>(steps / 50));
  const std::vector<std::int32_t> index_in_b = every_step.index_of_gid();
  double moved_last = 0;
  for (std::size_t i = 0; i < a.owned; ++i) {
    const auto j = static_cast<std::size_t>(index_in_b[a.gid[i]]);
    // The same contacts at the same steps: only the order of sums may differ between the lists.
    EXPECT_NEAR(a.position[i].x, b.position[j].x, 1e-12) << "gid " << a.gid[i];
    EXPECT_NEAR(a.position[i].y, b.position[j].y, 1e-12) << "gid " << a.gid[i];
    EXPECT_NEAR(a.velocity[i].x, b.velocity[j].x, 1e-10) << "gid " << a.gid[i];
    if (a.gid[i] == 4) moved_last = a.position[i].x - 0.06;
  }
  EXPECT_GT(moved_last, 1e-3) << "the collisions must have reached the end of the line";
}

constexpr int kSteps = 40000;  // the thrown cube reaches the first after some 5,000 steps; the last moves after 16,000

TEST(PairSleep, SleepingPairsGiveTheRunThatTestsEveryPairEveryStep) {
  expect_same_run(*cube_line(0, kSteps), *cube_line(1e-12, kSteps), kSteps);
}

// One point per part pair (crust GJK, as Huet et al. 2021): a pair GJK finds apart sleeps on the
// distance bound GJK returns, as the manifold's boxes sleep on their separating axis.
TEST(PairSleep, OnePointPairsSleepOnTheirGjkDistance) {
  set_composite_stats_enabled(true);
  reset_composite_stats();
  const auto sleeping = cube_line(0, kSteps, false);
  const std::uint64_t narrow_sleeping = composite_stats_total().narrow;
  reset_composite_stats();
  const auto every_step = cube_line(1e-12, kSteps, false);
  const std::uint64_t narrow_every_step = composite_stats_total().narrow;
  set_composite_stats_enabled(false);
  expect_same_run(*sleeping, *every_step, kSteps);
  // Here 1,112 narrow-phase queries against 4,206 (the manifold's boxes: 848).
  EXPECT_LT(narrow_sleeping * 3, narrow_every_step) << "apart pairs must not run GJK every step";
}

}  // namespace
}  // namespace talus
