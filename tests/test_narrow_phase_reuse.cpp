// Narrow-phase reuse (world/box_pair_reuse.h): a touching box pair served from its stored SAT
// feature gives the full query's contact to the bit while its reserve lasts, and runs the full
// query as soon as its motion has spent the reserve. In a World, reuse on and off give the same
// run (the stated tolerance is zero), a box resting on a box under tilted gravity sticks, and an
// elastic collision of boxes conserves energy as without reuse. The refit of face points on top
// (contact.manifold_refit) is bounded by its margin, keeps a resting box stuck and its energy,
// and leaves a slumping pile's runout within the scatter of its realisations; so does the
// recycling of points from anchors (contact.manifold_recycle), whose overlaps follow the full
// query's within a bound set by the motion.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "talus/collide/manifold.h"
#include "talus/contact/parameter_procedure.h"
#include "talus/scenario/cross_box.h"
#include "talus/scenario/rigid_body_type.h"
#include "talus/shape/convex_shape.h"
#include "talus/world/box_pair_reuse.h"
#include "talus/world/composite_stats.h"
#include "talus/world/world.h"
#include "test_random_poses.h"

namespace talus {
namespace {

using testing::random_rotation;
using testing::random_unit;

const double kPi = std::acos(-1.0);
using testing::kArm;
constexpr double kRadius = 13.6e-3;      // bounding radius of the cross the arm belongs to (m)

void expect_same_manifold(const ContactManifold& a, const ContactManifold& b, int trial, int step) {
  ASSERT_EQ(a.count, b.count) << "trial " << trial << " step " << step;
  ASSERT_EQ(a.normal, b.normal) << "trial " << trial << " step " << step;
  for (int k = 0; k < a.count; ++k) {
    ASSERT_EQ(a.points[k].feature_id, b.points[k].feature_id) << "trial " << trial << " step " << step;
    ASSERT_EQ(a.points[k].delta_n, b.points[k].delta_n) << "trial " << trial << " step " << step;
    ASSERT_EQ(a.points[k].point, b.points[k].point) << "trial " << trial << " step " << step;
  }
}

// Random touching arm pairs (crossed, face on face, edge on edge), each moved for 60 steps by a
// random walk of a cross in a pile (up to 1 um and 1e-4 rad a step, far more than a settled
// pile's nanometres): every step the contact served with reuse must equal the full query's.
TEST(BoxPairReuse, ServesTheFullQueryUnderSlowMotion) {
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> u(-1, 1), share(0, 1);
  const double turn_per_travel = 0.5 * kPi / kRadius;  // as composite_pair
  const Quat quarter = Quat::from_axis_angle({0, 0, 1}, kPi / 2);
  long steps = 0, reused = 0, full = 0;
  for (int trial = 0; trial < 400; ++trial) {
    Quat qa = random_rotation(rng), qb = random_rotation(rng);
    if (trial % 3 == 0) qb = qa * quarter;  // crossed arms, face on face
    if (trial % 3 == 1) qb = qa;            // parallel arms
    Pose pa{{0, 0, 0}, qa};
    Pose pb{{6e-3 * u(rng), 6e-3 * u(rng), 2.5e-3 * u(rng)}, qb};
    if (trial % 3 != 2) pb.position = qa.rotate({8e-3 * u(rng), 8e-3 * u(rng), 2.95e-3});  // b lies on a's face
    if (box_box_sat(oriented_box(kArm, pa), oriented_box(kArm, pb)).separated) continue;
    PartBudget budget;
    int stored_on = -1, stored_off = -1;
    double travelled = 0;
    const double speed = 1e-6 * share(rng), spin = 1e-4 * share(rng);
    const Vec3 drift = random_unit(rng), axis = random_unit(rng);
    for (int step = 0; step < 60; ++step) {
      const OrientedBox a = oriented_box(kArm, pa), b = oriented_box(kArm, pb);
      SatSource source = SatSource::stored_feature;
      const BoxBoxSat on = lasting_box_sat(a, b, stored_on, {travelled, turn_per_travel}, true, budget, &source);
      const BoxBoxSat off = box_box_sat(a, b, stored_off);  // the full query, as reuse off runs it
      ASSERT_EQ(on.axis, off.axis) << "trial " << trial << " step " << step;
      ASSERT_EQ(on.separated, off.separated);
      ASSERT_EQ(on.depth, off.depth) << "trial " << trial << " step " << step;
      ASSERT_EQ(on.normal, off.normal);
      expect_same_manifold(box_box_manifold(a, b, on), box_box_manifold(a, b, off), trial, step);
      ++steps;
      ++(source == SatSource::full ? full : reused);
      stored_on = on.separated ? -1 : on.axis;
      stored_off = off.separated ? -1 : off.axis;
      // Move b: a shift and a turn about its centre, its travel as PlacedBodies counts it.
      const double theta = spin * share(rng);
      pb.position += drift * speed;
      pb.orientation = (Quat::from_axis_angle(axis, theta) * pb.orientation).normalized();
      travelled += speed + 2 * kRadius * std::sin(theta / 2);
    }
  }
  std::printf("%ld steps of touching pairs: %ld served from the stored feature, %ld full queries\n", steps, reused,
              full);
  EXPECT_GT(steps, 8000);
  // Face-on-face pairs have edge axes along the face normal, whose overlaps tie with the face's:
  // their reserves are short, so a third of these (fast) steps are served.
  EXPECT_GT(reused, steps / 5);
}

// A pair turning steadily: reused exactly while the travel since the last full query is below
// its reserve, and a full query at the first step past it, which renews the reserve.
TEST(BoxPairReuse, TurnPastTheReserveRunsAFullQuery) {
  const double turn_per_travel = 0.5 * kPi / kRadius;
  const Pose pa{{0, 0, 0}, Quat{}};
  // Crossed at 80 degrees, slightly tilted (aligned boxes have parallel edges: no reserve), 10 um deep.
  Pose pb{{2e-3, 1e-3, 2.99e-3},
          (Quat::from_axis_angle({0, 0, 1}, 1.4) * Quat::from_axis_angle({1, 1, 0}, 1e-3)).normalized()};
  PartBudget budget;
  // The turn per step (about x: b tilts on a's face) is an eighth of the first reserve.
  SatSource first_source = SatSource::stored_feature;
  BoxBoxSat first = lasting_box_sat(oriented_box(kArm, pa), oriented_box(kArm, pb), -1, {0.0, turn_per_travel}, true,
                                    budget, &first_source);
  ASSERT_EQ(first_source, SatSource::full);
  ASSERT_FALSE(first.separated);
  ASSERT_GT(budget.until, 0.0);
  std::printf("reserve of the crossed pair: %.3g m\n", budget.until);
  const double dtheta = 2 * std::asin(budget.until / 8 / (2 * kRadius));
  budget = PartBudget{};
  int stored = -1, full_queries = 0, reused = 0;
  double travelled = 0, renewed_at = 0, reserve_end = 0;
  for (int step = 0; step < 100; ++step) {
    const OrientedBox a = oriented_box(kArm, pa), b = oriented_box(kArm, pb);
    SatSource source = SatSource::stored_feature;
    const bool within = stored >= 0 && travelled < reserve_end;
    const BoxBoxSat sat = lasting_box_sat(a, b, stored, {travelled, turn_per_travel}, true, budget, &source);
    ASSERT_FALSE(sat.separated) << "step " << step;
    EXPECT_EQ(source == SatSource::full, !within) << "step " << step << ", travel " << travelled - renewed_at << " m since the last full query";
    if (source == SatSource::full) {
      ++full_queries;
      renewed_at = travelled;
      reserve_end = budget.until;
      EXPECT_GE(reserve_end, travelled);
    } else {
      ++reused;
    }
    stored = sat.axis;
    pb.orientation = (Quat::from_axis_angle({1, 0, 0}, dtheta) * pb.orientation).normalized();
    travelled += 2 * kRadius * std::sin(dtheta / 2);
  }
  std::printf("turning pair: %d full queries, %d served from the stored feature\n", full_queries, reused);
  EXPECT_GE(full_queries, 3);  // the turn outran the reserve, more than once
  EXPECT_GT(reused, full_queries);
}

// Reuse off: every touching pair runs the full query.
TEST(BoxPairReuse, OffRunsTheFullQueryEveryStep) {
  PartBudget budget;
  const OrientedBox a = oriented_box(kArm, Pose{}),
                    b = oriented_box(kArm, Pose{{0, 0, 2.99e-3}, Quat::from_axis_angle({0, 0, 1}, kPi / 2)});
  int stored = -1;
  for (int step = 0; step < 3; ++step) {
    SatSource source = SatSource::stored_feature;
    stored = lasting_box_sat(a, b, stored, {0.0, 1.0}, false, budget, &source).axis;
    EXPECT_EQ(source, SatSource::full);
    EXPECT_FALSE(budget.asleep(0.0));
  }
}

struct PileRun {
  std::vector<Vec3> position, velocity, angular_velocity;
  std::vector<Quat> orientation;
  CompositeStats stats;
};

// Crosses poured into a box, left `settle` steps, then its x+ wall goes for `slump` steps.
PileRun cross_pile(const CrossBoxSetup& setup, int threads, unsigned long settle, unsigned long slump) {
  auto w = make_cross_box_world(setup);
  fill_cross_box(*w, setup);
  const int saved = omp_get_max_threads();
  omp_set_num_threads(threads);
  reset_composite_stats();
  set_composite_stats_enabled(true);
  w->run(settle);
  Wall& side = w->walls_mutable()[1];
  side.motion.kind = WallMotion::Kind::removed;
  side.motion.start_time = w->time();
  w->run(slump);
  set_composite_stats_enabled(false);
  omp_set_num_threads(saved);
  const ParticleStore& p = w->particles();
  PileRun r;
  r.stats = composite_stats_total();
  for (std::size_t i = 0; i < w->owned_count(); ++i) {
    r.position.push_back(p.position[i]);
    r.velocity.push_back(p.velocity[i]);
    r.angular_velocity.push_back(p.angular_velocity[i]);
    r.orientation.push_back(p.orientation[i]);
  }
  return r;
}

// 40 crosses dropped in a 6 x 6 cm box with the x+ wall gone after 20 ms, so that they land,
// pile and slump: falls, impacts and lasting contacts.
PileRun cross_pile(bool reuse, int threads) {
  CrossBoxSetup setup;
  setup.count = 40;
  setup.box = {0.06, 0.06, 0.03};
  setup.domain_hi = {0.2, 0.06, 0.2};
  setup.narrow_phase_reuse = reuse;
  setup.manifold_refit = 0;  // the exact reuse alone
  return cross_pile(setup, threads, 8000, 8000);
}

// The stated tolerance of reuse is zero: the same bits with reuse on (two threads) and off (one).
TEST(NarrowPhaseReuse, SameRunWithReuseOnAndOff) {
  const PileRun on = cross_pile(true, 2), off = cross_pile(false, 1);
  ASSERT_EQ(on.position.size(), off.position.size());
  for (std::size_t i = 0; i < on.position.size(); ++i) {
    ASSERT_EQ(on.position[i], off.position[i]) << "cross " << i;
    ASSERT_EQ(on.velocity[i], off.velocity[i]) << "cross " << i;
    ASSERT_EQ(on.angular_velocity[i], off.angular_velocity[i]) << "cross " << i;
    ASSERT_EQ(on.orientation[i].w, off.orientation[i].w) << "cross " << i;
    ASSERT_EQ(on.orientation[i].x, off.orientation[i].x) << "cross " << i;
  }
  const double share =
      static_cast<double>(on.stats.box_reused) / static_cast<double>(on.stats.box_reused + on.stats.box_full_queries);
  std::printf("reuse share %.3f (%llu served, %llu refit, %llu full queries; off: %llu full queries)\n", share,
              static_cast<unsigned long long>(on.stats.box_reused), static_cast<unsigned long long>(on.stats.box_refit),
              static_cast<unsigned long long>(on.stats.box_full_queries),
              static_cast<unsigned long long>(off.stats.box_full_queries));
  EXPECT_GT(on.stats.box_reused, 0u);
  EXPECT_EQ(off.stats.box_reused, 0u);
  // Pairs kept apart by their last separating axis sleep for that axis' gap, not the full
  // search's: the two runs query their apart pairs at different steps, their touching ones alike.
  EXPECT_GT(on.stats.box_apart_axis, 0u);
  EXPECT_EQ(off.stats.box_apart_axis, 0u);
  EXPECT_EQ(on.stats.box_touching, off.stats.box_touching);
}

struct TwoBoxes {
  std::unique_ptr<World> world;
  RigidBodyType body;
};

// A 1 cm cube (density 1000) on a fixed 10 x 10 x 2 cm slab, gravity g tilted by `tilt` about y.
TwoBoxes cube_on_slab(bool reuse, double tilt, double restitution, double friction, const Vec3& velocity,
                      const Vec3& spin, double height, double refit = 0, double recycle = 0) {
  WorldSettings s;
  s.domain = {{-1, -1, -1}, {1, 1, 1}};
  s.gravity = Vec3{std::sin(tilt), 0, -std::cos(tilt)} * 9.81;
  s.contact_manifold = true;
  s.narrow_phase_reuse = reuse;
  s.manifold_refit = refit;
  s.manifold_recycle = recycle;
  CompositeShape cube, slab;
  cube.add(make_box({0.005, 0.005, 0.005}, 2e-4), Pose{});
  slab.add(make_box({0.05, 0.05, 0.01}, 2e-4), Pose{});
  const RigidBodyType c = make_rigid_body_type(cube, 1000), b = make_rigid_body_type(slab, 1000);
  ContactParams k;
  k.normal_stiffness = 1e4;
  k.normal_damping.coefficient = params::normal_damping(k.normal_stiffness, c.mass, restitution);
  k.tangential_stiffness = 2.0 / 7.0 * k.normal_stiffness;
  k.tangential_damping = k.normal_damping;
  k.friction = friction;
  s.time_step = params::contact_time(k.normal_stiffness, c.mass / 4, 0.3) / 50;  // one of four points
  auto w = std::make_unique<World>(s);
  w->contacts().resize(1, 1);
  w->contacts().set_pair(0, 0, k);
  w->contacts().set_wall(0, 0, k);
  ParticleInit base = rigid_particle(b, w->add_shape(slab), {0, 0, 0}, Quat{}, 0);
  base.fixed = true;
  w->add_particle(base);
  ParticleInit top = rigid_particle(c, w->add_shape(cube), {0, 0, 0.01 + height}, Quat::from_axis_angle({1, 0.3, 0}, 0.02), 0);
  top.velocity = velocity;
  top.angular_velocity = spin;
  w->add_particle(top);
  return {std::move(w), c};
}

// The cube at rest on the slab under gravity tilted by 10 degrees: where it settled by t = 1 s,
// where it is at t = 1.5 s, and the contact counters over that last half second.
struct RestingCube {
  Vec3 settled, end, velocity;
  CompositeStats stats;
};

RestingCube resting_cube(bool reuse, double refit, double recycle = 0) {
  TwoBoxes t = cube_on_slab(reuse, 10 * kPi / 180, 0.3, 0.5, {}, {}, 0.0052, refit, recycle);
  World& w = *t.world;
  while (w.time() < 1.0) w.run(1000);
  RestingCube r;
  r.settled = w.particles().position[1];
  reset_composite_stats();
  set_composite_stats_enabled(true);
  while (w.time() < 1.5) w.run(1000);
  set_composite_stats_enabled(false);
  r.stats = composite_stats_total();
  r.end = w.particles().position[1];
  r.velocity = w.particles().velocity[1];
  std::printf("reuse %d, refit %g, recycle %g: drift over 0.5 s %.3g m, %llu served (%llu refit, %llu recycled), "
              "%llu full queries\n", reuse, refit, recycle, norm(r.end - r.settled),
              static_cast<unsigned long long>(r.stats.box_reused), static_cast<unsigned long long>(r.stats.box_refit),
              static_cast<unsigned long long>(r.stats.box_recycled),
              static_cast<unsigned long long>(r.stats.box_full_queries));
  return r;
}

// Gravity tilted by 10 degrees (tan = 0.18 < mu = 0.5): the cube lands, settles and sticks. With
// reuse it serves nearly every step from the stored feature and does not creep: its position
// over the last half second changes by less than a picometre, as without reuse (same bits).
TEST(NarrowPhaseReuse, RestingCubeOnABoxKeepsStaticFriction) {
  RestingCube run[2];
  for (int reuse = 0; reuse < 2; ++reuse) run[reuse] = resting_cube(reuse == 1, 0);
  EXPECT_EQ(run[0].end, run[1].end);
  EXPECT_LT(norm(run[1].end - run[1].settled), 1e-12);
  EXPECT_GT(run[1].stats.box_reused, 50 * run[1].stats.box_full_queries);
  EXPECT_EQ(run[0].stats.box_reused, 0u);
}

// No damping, no friction: a spinning cube thrown onto the slab bounces off. Kinetic plus
// elastic energy after the impact, relative to before, is the same with and without reuse (to
// the bit), and stays within the manifold's known drift (points appear and vanish with their
// share of k_n). With friction the manifold's springs restart when a point's features change,
// which loses a third of the energy in this impact, with or without reuse.
TEST(NarrowPhaseReuse, ElasticImpactEnergyUnchanged) {
  double ratio[2] = {0, 0};
  for (int reuse = 0; reuse < 2; ++reuse) {
    TwoBoxes t = cube_on_slab(reuse == 1, 0, 1.0, 0.0, {0.05, 0.02, -0.3}, {3, -2, 1}, 0.0058);
    World& w = *t.world;
    w.set_gravity({});
    const Diagnostics d0 = w.diagnostics();
    const double e0 = d0.kinetic() + d0.elastic();
    w.run(4000);
    const Diagnostics d1 = w.diagnostics();
    ASSERT_EQ(d1.contacts, 0u) << "the cube is still touching";
    ratio[reuse] = (d1.kinetic() + d1.elastic()) / e0;
    std::printf("reuse %d: E after / E before = %.12f\n", reuse, ratio[reuse]);
  }
  EXPECT_EQ(ratio[0], ratio[1]);
  EXPECT_NEAR(ratio[1], 1.0, 0.05);
}

// The refit's bound: after a clip at travel T with margin m, points are refit while the travels
// sum to less than T + m, never past the axis' own bound, and the float slack errs towards
// clipping sooner (by at most 2^-23 of the slack).
TEST(ManifoldRefit, MarginBoundsTheTravelOfARefit) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 10000; ++trial) {
    const double travelled = 10 * u(rng), reserve = 1e-3 * u(rng), margin = 1e-3 * u(rng) * u(rng);
    PartBudget budget{travelled + reserve, 3};
    EXPECT_FALSE(budget.refit_allowed(travelled)) << "no refit before a clip";
    budget.allow_refit(travelled, margin);
    const double bound = budget.until - static_cast<double>(budget.refit_slack);
    const double wanted = std::min(travelled + margin, budget.until);
    ASSERT_LE(bound, wanted) << "trial " << trial;
    ASSERT_GE(bound, wanted - 2.4e-7 * (budget.until - wanted) - 4e-16 * budget.until) << "trial " << trial;
    EXPECT_EQ(budget.refit_allowed(bound), false);
    budget.allow_refit(travelled, 0);
    EXPECT_FALSE(budget.refit_allowed(travelled)) << "a zero margin refits nothing";
  }
}

// A cube at rest on a slab under gravity tilted by 10 degrees, with the largest refit margin a
// scenario accepts: its four points (vertices of the cube, refit to the bit) are refit on most
// steps, and it sticks as without the refit.
TEST(ManifoldRefit, RestingCubeStaysStuck) {
  const RestingCube run = resting_cube(true, 0.5);
  const CompositeStats& stats = run.stats;
  EXPECT_LT(norm(run.end - run.settled), 1e-12);
  EXPECT_GT(stats.box_refit, stats.box_reused / 2);
}

// A cube thrown spinning onto the slab, no friction, no damping (as ElasticImpactEnergyUnchanged):
// kinetic plus elastic energy after the bounce over before.
double bounce_energy_ratio(double refit, double recycle) {
  TwoBoxes t = cube_on_slab(true, 0, 1.0, 0.0, {0.05, 0.02, -0.3}, {3, -2, 1}, 0.0058, refit, recycle);
  World& w = *t.world;
  w.set_gravity({});
  const Diagnostics d0 = w.diagnostics();
  w.run(4000);
  const Diagnostics d1 = w.diagnostics();
  EXPECT_EQ(d1.contacts, 0u) << "the cube is still touching";
  const double ratio = (d1.kinetic() + d1.elastic()) / (d0.kinetic() + d0.elastic());
  std::printf("refit %g, recycle %g: E after / E before = %.12f\n", refit, recycle, ratio);
  return ratio;
}

// A cube dropped tilted, which lands on an edge and turns onto its face: its points and where it
// rests at t = 0.5 s, and the contact counters.
struct Landing {
  std::size_t points;
  Vec3 rest;
  CompositeStats stats;
};
Landing tilted_landing(double refit, double recycle) {
  TwoBoxes t = cube_on_slab(true, 0, 0.3, 0.5, {}, {0, 0, 0}, 0.0052, refit, recycle);
  World& w = *t.world;
  reset_composite_stats();
  set_composite_stats_enabled(true);
  while (w.time() < 0.5) w.run(1000);
  set_composite_stats_enabled(false);
  const Landing l{w.diagnostics().contacts, w.particles().position[1], composite_stats_total()};
  std::printf("refit %g, recycle %g: %zu points at rest, %llu refit and %llu recycled of %llu served\n", refit, recycle,
              l.points, static_cast<unsigned long long>(l.stats.box_refit),
              static_cast<unsigned long long>(l.stats.box_recycled), static_cast<unsigned long long>(l.stats.box_reused));
  return l;
}

// The tilted cube ends face down on four points where it ends without the approximation.
void expect_same_landing(const Landing& exact, const Landing& approximate) {
  EXPECT_EQ(approximate.points, exact.points);
  EXPECT_LT(norm(approximate.rest - exact.rest), 1e-7);  // of a 1 cm cube
}

// With the refit, the turn past the margin brings the clip back, which finds the points coming
// down; the energy after the bounce is the exact reuse's within 1 % (the manifold's own drift is 5 %).
TEST(ManifoldRefit, TurningCubeFindsItsPointsAndKeepsItsEnergy) {
  EXPECT_NEAR(bounce_energy_ratio(0.5, 0), bounce_energy_ratio(0, 0), 0.01);
  const Landing refit = tilted_landing(0.5, 0);
  EXPECT_GT(refit.stats.box_refit, 0u);
  expect_same_landing(tilted_landing(0, 0), refit);
}

// 60 crosses poured into a 5 x 6 cm box and left to settle for 50 ms, then its x+ wall goes:
// the front of the slump 0.1 s later over three fillings, and the runs' contact counters.
struct Slump {
  double front[3];
  CompositeStats stats;
  double mean() const { return (front[0] + front[1] + front[2]) / 3; }
  double variance() const {
    double v = 0;
    for (double x : front) v += (x - mean()) * (x - mean()) / 2;
    return v;
  }
};
const Vec3 kSlumpBox{0.05, 0.06, 0.03};

Slump slumping_pile(double refit, double recycle) {
  Slump s;
  for (int seed = 0; seed < 3; ++seed) {
    CrossBoxSetup setup;
    setup.count = 60;
    setup.box = kSlumpBox;
    setup.domain_hi = {0.3, 0.06, 0.2};
    setup.seed = 1 + seed;
    setup.manifold_refit = refit;
    setup.manifold_recycle = recycle;
    const PileRun run = cross_pile(setup, 1, 20000, 40000);
    s.stats += run.stats;
    double x = 0;
    for (const Vec3& r : run.position) x = std::max(x, r.x);
    s.front[seed] = x;
  }
  return s;
}

// Both ensembles slump, and their means agree within twice the standard error of their
// difference (the ensemble scatter of three realisations).
void expect_same_slump(const Slump& exact, const Slump& approximate, const char* name) {
  for (const Slump* s : {&exact, &approximate}) {
    std::printf("%s %s: fronts %.4f %.4f %.4f m, mean %.4f +- %.4f\n", name, s == &exact ? "off" : "on", s->front[0],
                s->front[1], s->front[2], s->mean(), std::sqrt(s->variance() / 3));
    EXPECT_GT(s->mean(), kSlumpBox.x + 0.005) << name << (s == &exact ? " off" : " on") << ": no slump";
  }
  EXPECT_LT(std::abs(approximate.mean() - exact.mean()), 2 * std::sqrt((exact.variance() + approximate.variance()) / 3));
}

// The largest refit margin against clipping every step.
TEST(ManifoldRefit, SlumpingPileRunsOutAsWithoutRefit) {
  const Slump on = slumping_pile(0.5, 0);
  std::printf("%llu refits of %llu served\n", static_cast<unsigned long long>(on.stats.box_refit),
              static_cast<unsigned long long>(on.stats.box_reused));
  EXPECT_GT(on.stats.box_refit, 0u);
  expect_same_slump(slumping_pile(0, 0), on, "refit");
}

// Recycled points (contact.manifold_recycle), on random touching arm pairs of crosses (crossed,
// face on face, edge on edge) as ServesTheFullQueryUnderSlowMotion moves them: anchored once,
// then served from their anchors while b walks up to 1 um and turns up to 1e-4 rad a step, a
// fixed. Each point keeps its material points: one anchor on the reference face's plane (or an
// edge's line) and the other a point of the incident box (or the other edge). Their true overlap
// is their separation along the full query's normal (the same SAT axis), and the recycled one
// differs from it only through the normal's turn, which the anchors do not follow: by at most
// that turn times the travel plus the overlap times the turn squared. The normal turns with b's
// face, or for an edge pair a_i x b_j up to 1/|a_i x b_j| times faster than b; for a reference
// face of a it does not turn, and the overlap is exact. (A clipped point where an incident edge
// crosses a side plane slides along that edge as the boxes move; the anchored one stays a
// material point, whose overlap this is.) At zero motion the points come back to rounding.
TEST(ManifoldRecycle, AnchoredOverlapFollowsTheFullQuery) {
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> u(-1, 1), share(0, 1);
  const Quat quarter = Quat::from_axis_angle({0, 0, 1}, kPi / 2);
  long compared = 0;
  double worst_ratio = 0;
  for (int trial = 0; trial < 300; ++trial) {
    Quat qa = random_rotation(rng), qb = random_rotation(rng);
    if (trial % 3 == 0) qb = qa * quarter;
    if (trial % 3 == 1) qb = qa;
    const Pose pa{{0, 0, 0}, qa};
    Pose pb{{6e-3 * u(rng), 6e-3 * u(rng), 2.5e-3 * u(rng)}, qb};
    if (trial % 3 != 2) pb.position = qa.rotate({8e-3 * u(rng), 8e-3 * u(rng), 2.95e-3});
    const OrientedBox a = oriented_box(kArm, pa);
    const BoxBoxSat sat0 = box_box_sat(a, oriented_box(kArm, pb));
    if (sat0.separated) continue;
    const ContactManifold m0 = box_box_manifold(a, oriented_box(kArm, pb), sat0);
    std::vector<PointAnchors> anchors;
    for (int k = 0; k < m0.count; ++k) {
      if (!(m0.points[k].delta_n > 0)) continue;
      const PointAnchors at = anchors_of(a, oriented_box(kArm, pb), m0.normal, m0.points[k].point, m0.points[k].delta_n);
      const AnchoredPoint back = from_anchors(a, oriented_box(kArm, pb), at);
      ASSERT_NEAR(back.overlap, m0.points[k].delta_n, 1e-17) << "trial " << trial;
      ASSERT_LT(norm(back.point - m0.points[k].point), 1e-17) << "trial " << trial;
      ASSERT_LT(norm(back.normal - m0.normal), 4e-15) << "trial " << trial;
      anchors.push_back(at);
    }
    const double speed = 1e-6 * share(rng), spin = 1e-4 * share(rng);
    const Vec3 drift = random_unit(rng), axis = random_unit(rng);
    const OrientedBox b0 = oriented_box(kArm, pb);
    const double speed_up =
        sat0.axis < 6 ? 1.0 : 1.0 / norm(cross(a.axis[(sat0.axis - 6) / 3], b0.axis[(sat0.axis - 6) % 3]));
    double travel = 0, turn = 0;
    for (int step = 0; step < 30; ++step) {
      const double theta = spin * share(rng);
      pb.position += drift * speed;
      pb.orientation = (Quat::from_axis_angle(axis, theta) * pb.orientation).normalized();
      travel += speed + 2 * kRadius * std::sin(theta / 2);
      turn += theta;
      const OrientedBox b = oriented_box(kArm, pb);
      const BoxBoxSat sat = box_box_sat(a, b, sat0.axis);
      if (sat.separated || sat.axis != sat0.axis) break;  // the feature is gone: a full query would run
      const Vec3 n = sat.normal;
      const double normal_turn = sat.axis < 3 ? 0.0 : 1.01 * speed_up * turn;  // 1 %: the edges' angle changes
      for (const PointAnchors& k : anchors) {
        const AnchoredPoint r = from_anchors(a, b, k);
        const Vec3 x_i = a.centre + turned_with(a, k.deepest_i), x_j = b.centre + turned_with(b, k.deepest_j);
        const double truth = dot(x_j - x_i, n);
        const double bound = normal_turn * travel + std::abs(truth) * normal_turn * normal_turn + 1e-15;
        const double error = std::abs(r.overlap - truth);
        ASSERT_LE(error, bound) << "trial " << trial << " step " << step << " axis " << sat.axis;
        ASSERT_LE(norm(r.normal - n), normal_turn + 4e-15) << "trial " << trial << " step " << step;
        if (sat.axis >= 6) {  // the anchors stay on the edges' lines: the full query's overlap itself
          const ManifoldPoint q = box_box_edge_point(a, b, sat);
          ASSERT_LE(std::abs(truth - q.delta_n), 1e-15) << "trial " << trial << " step " << step;
        }
        worst_ratio = std::max(worst_ratio, error / bound);
        ++compared;
      }
    }
  }
  std::printf("%ld recycled points compared with the full query, worst error %.3g of its bound\n", compared, worst_ratio);
  EXPECT_GT(compared, 3000);
}

// Recycling's bound: points computed at travel T with margin m are recycled while the travels
// sum to less than T + m and the stored axis is still the budget's, never with a zero margin,
// with reuse off, or for another axis; a pair turning past the margin computes them again.
TEST(ManifoldRecycle, MarginBoundsTheTravelOfARecycle) {
  const Reuse on{true, 0, true, 2e-6}, no_margin{true, 0, true, 0}, off{false, 0, true, 2e-6};
  const double travelled = 3e-3;
  PartBudget budget{travelled + 1e-5, 7};  // edge axis 7 holds for 10 um more
  EXPECT_FALSE(recycle_allowed(on, budget, 7, travelled)) << "nothing to recycle before the points are computed";
  budget.allow_refit(travelled, on.recycle);
  EXPECT_TRUE(recycle_allowed(on, budget, 7, travelled + 1e-6));
  EXPECT_FALSE(recycle_allowed(on, budget, 7, travelled + 2.001e-6)) << "past the margin";
  EXPECT_FALSE(recycle_allowed(on, budget, 3, travelled + 1e-6)) << "another axis";
  EXPECT_FALSE(recycle_allowed(no_margin, budget, 7, travelled + 1e-6));
  EXPECT_FALSE(recycle_allowed(off, budget, 7, travelled + 1e-6));
  // A pair turning steadily by a tenth of the margin a step: recycled for nine steps in ten.
  int recycled = 0, computed = 0;
  PartBudget turning{1.0, 7};
  double t = 0;
  for (int step = 0; step < 100; ++step, t += 2e-7) {
    if (recycle_allowed(on, turning, 7, t)) {
      ++recycled;
    } else {
      ++computed;
      turning.allow_refit(t, on.recycle);
    }
  }
  std::printf("turning pair: %d steps recycled, %d computed\n", recycled, computed);
  EXPECT_GE(computed, 10);
  EXPECT_LE(computed, 11);
}

// A cube at rest on a slab under gravity tilted by 10 degrees, its points recycled for 1 um of
// travel (its drift is picometres, so nearly every step is recycled): it sticks as without.
TEST(ManifoldRecycle, RestingCubeStaysStuck) {
  const RestingCube run = resting_cube(true, 0, 1e-6);
  const CompositeStats& stats = run.stats;
  EXPECT_LT(norm(run.end - run.settled), 1e-12);
  EXPECT_GT(stats.box_recycled, 9 * stats.box_reused / 10);
}

// With a recycle margin of 10 um: the energy after the bounce is the exact reuse's within 1 %
// (the spin spends the feature's reserve at every step of the bounce, so little is recycled
// there), and the tilted cube, recycled as it turns and rests, finds the points coming down.
TEST(ManifoldRecycle, TurningCubeFindsItsPointsAndKeepsItsEnergy) {
  EXPECT_NEAR(bounce_energy_ratio(0, 1e-5), bounce_energy_ratio(0, 0), 0.01);
  const Landing recycled = tilted_landing(0, 1e-5);
  EXPECT_GT(recycled.stats.box_recycled, recycled.stats.box_reused / 2);
  expect_same_landing(tilted_landing(0, 0), recycled);
}

// The slumping pile recycled for 2 um of travel, against computed every step.
TEST(ManifoldRecycle, SlumpingPileRunsOutAsWithoutRecycle) {
  const Slump on = slumping_pile(0, 2e-6);
  std::printf("%llu recycled of %llu served\n", static_cast<unsigned long long>(on.stats.box_recycled),
              static_cast<unsigned long long>(on.stats.box_reused));
  EXPECT_GT(on.stats.box_recycled, on.stats.box_reused / 2);
  expect_same_slump(slumping_pile(0, 0), on, "recycle");
}

}  // namespace
}  // namespace talus
