// Rigid crosses (two cuboids each, Huet et al. 2021) spread over the ranks against the same
// world on one rank: a stack of two sliding across a cut with its contact points, and a
// throng thrown at the floor that collides across the cuts, many crosses straddling a cut.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <utility>

#include "talus/parallel/communicator.h"
#include "talus/scenario/cross_box.h"
#include "talus/scenario/rigid_body_type.h"

namespace talus {
namespace {

// 120 crosses in a 24 x 3 cm box, from its floor up, thrown down at 1 m/s with
// horizontal speeds up to 0.3 m/s.
std::unique_ptr<World> thrown_crosses() {
  CrossBoxSetup setup;
  setup.count = 120;
  setup.box = {0.24, 0.03, 0.03};
  setup.domain_hi = {0.24, 0.03, 0.3};
  auto world = make_cross_box_world(setup);
  fill_cross_box(*world, setup);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> side(-0.3, 0.3);
  ParticleStore& p = world->particles_mutable();
  for (std::size_t i = 0; i < p.owned; ++i) p.velocity[i] = {side(rng), side(rng), -1.0};
  return world;
}

// The largest distance and half-angle between the crosses of `spread` (over all ranks) and
// those of `reference`; fails if a cross is owned by no rank or by two.
std::pair<double, double> worst_difference(const Communicator& comm, const World& reference, const World& spread) {
  const ParticleStore& p = spread.particles();
  const ParticleStore& q = reference.particles();
  std::vector<double> mine(5 * q.owned, 0.0);
  const std::vector<std::int32_t> index = reference.index_of_gid();
  for (std::size_t i = 0; i < p.owned; ++i) {
    const std::int32_t k = index[p.gid[i]];
    for (int a = 0; a < 3; ++a) mine[5 * k + a] = p.position[i][a] - q.position[k][a];
    const Quat d = p.orientation[i] * q.orientation[k].conjugate();
    mine[5 * k + 3] = std::hypot(d.x, d.y, d.z);
    mine[5 * k + 4] = 1;
  }
  comm.sum_in_place(mine);
  double worst = 0, worst_turn = 0;
  for (std::size_t k = 0; k < q.owned; ++k) {
    EXPECT_EQ(mine[5 * k + 4], 1) << "cross at " << k << " owned by no rank or by two";
    worst = std::max(worst, std::hypot(mine[5 * k], mine[5 * k + 1], mine[5 * k + 2]));
    worst_turn = std::max(worst_turn, mine[5 * k + 3]);
  }
  return {worst, worst_turn};
}

// The spread world follows the reference to round-off: crosses within 1e-12 m and 1e-10 rad,
// the same contacts on crosses and walls, the same elastic energy of their springs.
void expect_same_as_one_rank(const Communicator& comm, const World& reference, const World& spread) {
  const auto [worst, worst_turn] = worst_difference(comm, reference, spread);
  EXPECT_LT(worst, 1e-12);
  EXPECT_LT(worst_turn, 1e-10);
  const Diagnostics a = reference.diagnostics(), b = spread.diagnostics();
  EXPECT_EQ(b.contacts, a.contacts);
  EXPECT_EQ(b.wall_contacts, a.wall_contacts);
  EXPECT_NEAR(b.elastic_tangential, a.elastic_tangential, 1e-6 * a.elastic_tangential);
}

std::vector<double> cuts_along_x(const Communicator& comm, double length) {
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> cut{-inf};
  for (int r = 1; r < comm.size(); ++r) cut.push_back(length * r / comm.size());
  cut.push_back(inf);
  return cut;
}

// Cross B lies on cross A, turned by 45 degrees, and both slide along x over the floor at
// 0.5 m/s. The floor's friction (0.62) brakes A harder than A's (0.46) can brake B, so B slides
// on A: their contact points stay in contact, springs at the Coulomb limit, as A and B cross
// the cut at x = 0.12 m and move to the next rank.
std::unique_ptr<World> sliding_stack() {
  CrossBoxSetup setup;
  setup.box = {0.24, 0.06, 0.03};
  setup.domain_hi = {0.24, 0.06, 0.1};
  auto world = make_cross_box_world(setup);
  const RigidBodyType type = huet_cross_type(setup.crust);
  const Quat turned = Quat::from_axis_angle({0, 0, 1}, 0.25 * std::numbers::pi);
  world->add_particle(rigid_particle(type, 1, {0.104, 0.03, 1.5e-3 + 2e-5}, Quat{}, 0));
  world->add_particle(rigid_particle(type, 1, {0.104, 0.03, 4.5e-3 + 6e-5}, turned, 0));
  ParticleStore& p = world->particles_mutable();
  for (std::size_t i = 0; i < p.owned; ++i) p.velocity[i] = {0.5, 0, 0};
  return world;
}

// Runs the stack until B rests on A. With e = 0.85 the landing chatters (the points between A
// and B come and go for some 10 ms), and the step on which it settles moves with the last bits
// of the cross's inertia: a fixed step count found it in the air.
void run_until_stacked(World& w) {
  w.run(8000);
  for (int k = 0; k < 16 && w.diagnostics().contacts == 0; ++k) w.run(500);
}

TEST(DistributedCrosses, StackSlidesAcrossTheCutSameAsOneRank) {
  const Communicator& comm = Communicator::world();
  auto reference = sliding_stack();
  auto spread = sliding_stack();
  run_until_stacked(*reference);  // landed: B on A, A on the floor, both sliding
  run_until_stacked(*spread);
  ASSERT_GT(reference->diagnostics().contacts, 0u);
  const std::vector<double> cut = cuts_along_x(comm, 0.24);
  spread->distribute(RankGrid::slabs(comm, spread->settings().domain, 0, cut, 0.05));
  reference->run(32000);  // 0.1 s in all: the stack has stopped past the cut
  spread->run(32000);
  expect_same_as_one_rank(comm, *reference, *spread);
  const ParticleStore& q = reference->particles();
  EXPECT_GT(q.position[0].x, 0.121);  // both crossed the cut
  EXPECT_GT(q.position[1].x, 0.121);
  EXPECT_GT(reference->diagnostics().contacts, 0u);  // B still lies on A
  if (comm.size() > 1) EXPECT_EQ(comm.sum(static_cast<double>(spread->particles_moved_between_ranks())), 2);
}

TEST(DistributedCrosses, ThrownCrossesSameAsOneRank) {
  const Communicator& comm = Communicator::world();
  auto reference = thrown_crosses();
  auto spread = thrown_crosses();
  reference->run(16000);
  spread->run(16000);
  // The crosses have landed and collide, briefly (a contact lasts about 50 steps): some points
  // are live as the world is spread (14 between crosses and 3 on walls, here).
  ASSERT_GT(reference->diagnostics().contacts, 0u);
  ASSERT_GT(reference->diagnostics().wall_contacts, 0u);
  const std::vector<double> cut = cuts_along_x(comm, 0.24);
  spread->distribute(RankGrid::slabs(comm, spread->settings().domain, 0, cut, 0.05));
  // Colliding crosses are chaotic: a difference in the last bit (the sums of a body's contacts
  // run in another order once the ranks' lists differ) grows tenfold every 100-200 steps,
  // measured on 2 ranks: 1e-17 m after 200 steps, 1e-15 after 400, 1e-12 after 740, 0.7 mm
  // after 8000. So 500 steps, in which the contacts across the cuts come and go.
  reference->run(500);
  spread->run(500);
  expect_same_as_one_rank(comm, *reference, *spread);
  // Crosses straddle the cuts: their centres within a bounding radius of one.
  std::size_t straddling = 0;
  const ParticleStore& p = spread->particles();
  for (std::size_t i = 0; i < p.owned; ++i)
    for (std::size_t c = 1; c + 1 < cut.size(); ++c) straddling += std::abs(p.position[i].x - cut[c]) < p.radius[i];
  if (comm.size() > 1) EXPECT_GT(comm.sum(static_cast<double>(straddling)), 0);
}

// Cuts along x and, from four ranks on, along `second`, at `at`: a grid of 2 x 2 boxes.
RankGrid corner_grid(const Communicator& comm, const Domain& domain, int second, const Vec3& at, int slab_axis) {
  const double inf = std::numeric_limits<double>::infinity();
  std::array<std::vector<double>, 3> cut;
  if (comm.size() >= 2) cut[0] = {-inf, at.x, inf};
  if (comm.size() >= 4) cut[second] = {-inf, at[second], inf};
  return RankGrid::with_cuts(comm, domain, cut, 0.02, comm.size() >= 4 ? slab_axis : 0);
}

// The sliding stack again, now moving across x and y, B ahead of A in both. The grid's corner
// lies just ahead of A's centre on A's path, so that B's box is the one diagonally across from
// A's: A's box lists the pair, and A then passes both cuts before the next rebuild, through a
// neighbour, where the pair's memory (springs and contact points) must follow it.
TEST(DistributedCrosses, StackSlidesAcrossACornerSameAsOneRank) {
  const Communicator& comm = Communicator::world();
  if (comm.size() != 1 && comm.size() != 2 && comm.size() != 4) GTEST_SKIP() << "a 2 x 2 grid needs 1, 2 or 4 ranks";
  for (const int slab_axis : {0, 1}) {
    auto reference = sliding_stack();
    auto spread = sliding_stack();
    for (World* w : {reference.get(), spread.get()}) {
      run_until_stacked(*w);  // landed, sliding along x
      ASSERT_GT(w->diagnostics().contacts, 0u);
      ParticleStore& p = w->particles_mutable();
      p.velocity[0].y += 0.15;  // and now along y too, B faster
      p.velocity[1].y += 0.2;
      w->run(2000);
    }
    const ParticleStore& q = reference->particles();
    const Vec3 a = q.position[0], b = q.position[1], corner = a + 2e-5 * q.velocity[0];
    ASSERT_TRUE(b.x > corner.x && b.y > corner.y) << "B is not ahead of A";
    spread->distribute(corner_grid(comm, spread->settings().domain, 1, corner, slab_axis));
    reference->run(6000);  // the stack's springs stay loaded: B still slides on A
    spread->run(6000);
    expect_same_as_one_rank(comm, *reference, *spread);
    EXPECT_GT(reference->diagnostics().contacts, 0u);  // B still lies on A
  }
}

// The thrown crosses on a grid cut along x and z (at 12 mm, through the pile): crosses collide
// across both cuts and their edge.
TEST(DistributedCrosses, ThrownCrossesOnAGridSameAsOneRank) {
  const Communicator& comm = Communicator::world();
  if (comm.size() != 1 && comm.size() != 2 && comm.size() != 4) GTEST_SKIP() << "a 2 x 2 grid needs 1, 2 or 4 ranks";
  for (const int slab_axis : {0, 2}) {
    auto reference = thrown_crosses();
    auto spread = thrown_crosses();
    reference->run(16000);
    spread->run(16000);
    spread->distribute(corner_grid(comm, spread->settings().domain, 2, {0.12, 0, 0.012}, slab_axis));
    reference->run(500);
    spread->run(500);
    expect_same_as_one_rank(comm, *reference, *spread);
  }
}

}  // namespace
}  // namespace talus
