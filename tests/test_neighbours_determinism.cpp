// The half neighbour list against brute force (periodic images included), and results that
// do not depend on the number of threads.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <random>

#include "talus/scenario/chute.h"
#include "talus/scenario/cross_box.h"
#include "talus/world/world.h"
#include "test_world_helpers.h"

namespace talus {
namespace {

TEST(Neighbours, PeriodicContactsMatchBruteForce) {
  WorldSettings s;
  s.domain = {{0, 0, 0}, {6, 5, 7}};
  s.domain.periodic[0] = s.domain.periodic[1] = s.domain.periodic[2] = true;
  s.gravity = {};
  s.time_step = 1e-6;
  World w(s);
  w.contacts().resize(1, 1);
  ContactParams c;
  c.normal_stiffness = 1e3;
  w.contacts().set_pair(0, 0, c);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  for (int k = 0; k < 3000; ++k) {
    ParticleInit p = testing::sphere({6 * u(rng), 5 * u(rng), 7 * u(rng)}, 0.25 + 0.2 * u(rng), 1.0);
    w.add_particle(p);
  }
  w.step();
  const Snapshot snap = w.snapshot();
  std::size_t brute = 0;
  double brute_energy = 0;
  for (std::size_t i = 0; i < snap.particles.size(); ++i)
    for (std::size_t j = i + 1; j < snap.particles.size(); ++j) {
      const Vec3 d = s.domain.minimum_image(snap.particles[i].position - snap.particles[j].position);
      const double overlap = snap.particles[i].radius + snap.particles[j].radius - norm(d);
      if (overlap > 0) ++brute, brute_energy += 0.5 * c.normal_stiffness * overlap * overlap;
    }
  const Diagnostics d = w.diagnostics();
  EXPECT_GT(brute, 1000u);
  EXPECT_EQ(d.contacts, brute);
  EXPECT_NEAR(d.elastic_normal / brute_energy, 1.0, 1e-12);
  // Newton's third law: the contact forces sum to zero.
  Vec3 total;
  for (const ContactRecord& r : snap.contacts) total += r.force - r.force;  // each pair listed once
  Vec3 net;
  for (std::size_t i = 0; i < w.particles().owned; ++i) net += w.particles().force[i];
  EXPECT_LT(norm(net), 1e-9 * c.normal_stiffness);
  // Every particle's force is the brute-force sum of k_n delta_n n over its overlapping
  // neighbours (at rest: no damping, no tangential force). Crowded rows (up to a dozen
  // neighbours) cross the eight-entry steps of the vector distance test.
  const ParticleStore& p = w.particles();
  for (std::size_t i = 0; i < p.owned; ++i) {
    Vec3 expected;
    for (std::size_t j = 0; j < p.owned; ++j) {
      if (j == i) continue;
      const Vec3 d = s.domain.minimum_image(p.position[i] - p.position[j]);
      const double overlap = p.radius[i] + p.radius[j] - norm(d);
      if (overlap > 0) expected += c.normal_stiffness * overlap * d / norm(d);
    }
    ASSERT_LT(norm(p.force[i] - expected), 1e-9 * c.normal_stiffness) << "particle " << i;
  }
}

std::vector<Vec3> run_chute(int threads) {
  omp_set_num_threads(threads);
  ChuteSetup s;
  s.flow = s.base = weinhart_chute_contact();
  s.base_diameter = 0;  // flat base: quick to build
  s.fill_height = 12;   // 2400 particles: enough to run in parallel
  s.angle_deg = 26;
  auto w = build_chute(s);
  w->run(1500);
  const Snapshot snap = w->snapshot();
  std::vector<Vec3> x;
  for (const auto& p : snap.particles) x.push_back(p.position);
  return x;
}

TEST(Determinism, SameResultsOnOneAndTwoThreads) {
  const int before = omp_get_max_threads();
  const std::vector<Vec3> one = run_chute(1);
  const std::vector<Vec3> two = run_chute(2);
  const std::vector<Vec3> again = run_chute(2);
  omp_set_num_threads(before);
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    ASSERT_EQ(one[i], two[i]) << "particle " << i;
    ASSERT_EQ(two[i], again[i]) << "particle " << i;
  }
}

// Every mobile particle's full state, bit for bit.
void expect_same_state(const World& a, const World& b) {
  const ParticleStore &p = a.particles(), &q = b.particles();
  ASSERT_EQ(p.owned, q.owned);
  for (std::size_t i = 0; i < p.owned; ++i) {
    ASSERT_EQ(p.position[i], q.position[i]) << "particle " << i;
    ASSERT_EQ(p.velocity[i], q.velocity[i]) << "particle " << i;
    ASSERT_EQ(p.angular_velocity[i], q.angular_velocity[i]) << "particle " << i;
    const Quat &r = p.orientation[i], &t = q.orientation[i];
    ASSERT_TRUE(r.w == t.w && r.x == t.x && r.y == t.y && r.z == t.z) << "particle " << i;
  }
}

// A small flowing chute: Weinhart et al. 2012 contacts, a flat base, four layers.
ChuteSetup four_layer_chute() {
  ChuteSetup s;
  s.flow = s.base = weinhart_chute_contact();
  s.base_diameter = 0;
  s.fill_height = 4;
  s.angle_deg = 26;
  return s;
}

// World::run fuses the closing half kick of a step with the opening one of the next; the
// result must be that of single steps, to the bit, with neighbour rebuilds in between.
TEST(Determinism, ARunOfStepsEqualsSingleSteps) {
  const ChuteSetup s = four_layer_chute();
  auto fused = build_chute(s), single = build_chute(s);
  // 6,000 steps (0.6 sqrt(d/g)): the spheres, placed clear of the flat base, fall and slide more
  // than half a skin, so the lists are rebuilt in between.
  fused->run(6000);
  for (int k = 0; k < 6000; ++k) single->step();
  EXPECT_GT(fused->rebuilds(), 1u);
  expect_same_state(*fused, *single);

  CrossBoxSetup c;
  c.count = 60;
  c.box = {0.06, 0.06, 0.04};
  c.domain_hi = {0.06, 0.06, 0.3};
  auto crosses = make_cross_box_world(c), crosses_single = make_cross_box_world(c);
  for (World* w : {crosses.get(), crosses_single.get()}) {
    fill_cross_box(*w, c);
    ParticleStore& p = w->particles_mutable();  // thrown down at unequal speeds: they collide soon
    for (std::size_t i = 0; i < p.owned; ++i) {
      p.velocity[i] = {0, 0, -1.0 - 0.5 * static_cast<double>(i % 3)};
      p.angular_velocity[i] = {20.0 * static_cast<double>(i % 5), 0, 10};
    }
  }
  std::size_t contacts = 0, wall_contacts = 0;  // seen at the ends of the runs
  for (int run = 0; run < 30; ++run) {
    crosses->run(400);
    for (int k = 0; k < 400; ++k) crosses_single->step();
    const Diagnostics d = crosses->diagnostics();
    contacts += d.contacts;
    wall_contacts += d.wall_contacts;
  }
  EXPECT_GT(contacts, 20u);
  EXPECT_GT(wall_contacts, 10u);  // 20-34 seen, with the compiler and machine
  expect_same_state(*crosses, *crosses_single);
}

// Sphere worlds end each particle's step inside the force pass (World::run). It must give the
// bits of separate passes: on a chute of several chunks of slabs (so the first slabs of even
// chunks wait for the odd ones), with periodic ghosts, and with a lid the grains are thrown
// against (their steps end after the wall forces).
TEST(Determinism, StepsEndedInTheForcePassEqualSeparatePasses) {
  const ChuteSetup s = four_layer_chute();
  auto fused = build_chute(s), separate = build_chute(s);
  separate->set_fused_step_end(false);
  for (World* w : {fused.get(), separate.get()}) {
    ContactTable& table = w->contacts();
    const ContactTable pairs = table;
    table.resize(pairs.species(), 1);
    for (int a = 0; a < pairs.species(); ++a) {
      for (int b = 0; b < pairs.species(); ++b) table.set_pair(a, b, pairs.pair(a, b));
      table.set_wall(a, 0, pairs.pair(a, a));
    }
    Wall lid;
    lid.origin = {0, 0, 6};
    lid.normal = {0, 0, -1};
    w->add_wall(lid);
    ParticleStore& p = w->particles_mutable();
    for (std::size_t i = 0; i < p.owned; ++i)
      if (p.inv_mass[i] != 0) p.velocity[i] = {0, 0, 4.0 + 0.5 * static_cast<double>(i % 3)};
  }
  std::size_t wall_contacts = 0;
  for (int run = 0; run < 10; ++run) {
    fused->run(60);
    separate->run(60);
    wall_contacts += fused->diagnostics().wall_contacts;
  }
  EXPECT_GE(fused->pair_list().slab_chunks().size(), 9u);  // at least eight chunks
  EXPECT_GT(fused->rebuilds(), 2u);
  EXPECT_GT(wall_contacts, 20u);
  expect_same_state(*fused, *separate);
}

// Without walls the owners of ghosts end their steps and refresh their ghosts with their slab
// when all their ghosts share it, the others in a pass of their own after the pair pass;
// runs of a few steps each also test the ghosts between two calls of World::run. The grains
// are thrown at one another and at the base, so that contacts cross the periodic faces.
TEST(Determinism, StepsEndedWithTheGhostRefreshEqualSeparatePasses) {
  ChuteSetup s = four_layer_chute();
  s.base_diameter = 1;  // a rough base of fixed spheres: no wall
  auto fused = build_chute(s), separate = build_chute(s);
  ASSERT_TRUE(fused->walls().empty());
  separate->set_fused_step_end(false);
  for (World* w : {fused.get(), separate.get()}) {
    ParticleStore& p = w->particles_mutable();
    for (std::size_t i = 0; i < p.owned; ++i) {
      const double k = static_cast<double>(i);
      if (p.inv_mass[i] != 0) p.velocity[i] = {6 * std::sin(k), 6 * std::cos(1.7 * k), -3 - 2 * std::sin(0.3 * k)};
    }
  }
  for (int run = 0; run < 40; ++run) {
    fused->run(1 + run % 4);
    separate->run(1 + run % 4);
  }
  std::size_t contacts = 0;  // seen at the ends of the runs
  for (int run = 0; run < 10; ++run) {
    fused->run(100);
    separate->run(100);
    contacts += fused->diagnostics().contacts;
  }
  EXPECT_GT(fused->particles().size(), fused->owned_count());  // periodic ghosts
  EXPECT_GT(fused->rebuilds(), 2u);
  EXPECT_GT(contacts, 100u);
  expect_same_state(*fused, *separate);
}

}  // namespace
}  // namespace talus
