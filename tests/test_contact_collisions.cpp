// Binary collisions against the closed-form linear spring-dashpot (Weinhart et al. 2012,
// Eqs. 5-6; Huet et al. 2021, Eqs. 5, 11-12).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "talus/contact/parameter_procedure.h"
#include "talus/world/world.h"

namespace talus {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDensity = 6 / kPi;  // d = 1 spheres of unit mass

ContactParams chute_params() {
  ContactParams c;
  c.normal_stiffness = 2e5;
  c.normal_damping.per_reduced_mass = 50;  // Silbert convention (seeds README)
  c.tangential_stiffness = 2.0 / 7.0 * 2e5;
  c.tangential_damping.per_reduced_mass = 50;
  c.friction = 0.5;
  return c;
}

struct Collision {
  double duration = 0;
  double restitution = 0;
};

// Runs a head-on collision along x at relative speed 1 and measures the contact duration and
// the ratio of the normal relative speeds after and before.
Collision head_on(TangentialModel model, bool against_wall, double dt) {
  WorldSettings s;
  s.domain = {{-10, -10, -10}, {10, 10, 10}};
  s.gravity = {};
  s.time_step = dt;
  s.tangential_model = model;
  World w(s);
  w.contacts().resize(1, 1);
  w.contacts().set_pair(0, 0, chute_params());
  w.contacts().set_wall(0, 0, chute_params());
  ParticleInit a;
  a.radius = 0.5;
  a.mass = 1;
  a.inertia = {0.1 * 0.25, 0.1 * 0.25, 0.1 * 0.25};
  if (against_wall) {
    Wall wall;
    wall.origin = {0, 0, 0};
    wall.normal = {1, 0, 0};
    w.add_wall(wall);
    a.position = {0.5 + 1e-4, 0, 0};
    a.velocity = {-1, 0, 0};
    w.add_particle(a);
  } else {
    a.position = {-0.5 - 1e-4, 0, 0};
    a.velocity = {0.5, 0, 0};
    w.add_particle(a);
    a.position = {0.5 + 1e-4, 0, 0};
    a.velocity = {-0.5, 0, 0};
    w.add_particle(a);
  }
  auto relative = [&] {
    const auto& p = w.particles();
    if (against_wall) return p.velocity[0].x;
    const std::size_t i = p.gid[0] == 0 ? 0 : 1;
    return p.velocity[1 - i].x - p.velocity[i].x;
  };
  Collision c;
  int steps_in_contact = 0;
  bool touched = false;
  for (int k = 0; k < 200000; ++k) {
    w.step();
    const bool touching = w.diagnostics().contacts + w.diagnostics().wall_contacts > 0;
    if (touching) ++steps_in_contact, touched = true;
    if (touched && !touching) break;
  }
  c.duration = steps_in_contact * dt;
  c.restitution = std::abs(relative()) / 1.0;
  return c;
}

TEST(ContactCollision, ElasticSpringPairMatchesCollisionTimeAndRestitution) {
  const double tc = params::collision_time(2e5, 25, 0.5);  // eta = 50 m_ij, m_ij = 1/2
  const double e = params::restitution_from_collision(2e5, 25, 0.5);
  EXPECT_NEAR(tc, 0.00497, 1e-5);  // the seeds README: t_c = 0.00497, e = 0.883
  EXPECT_NEAR(e, 0.883, 1e-3);
  const Collision c = head_on(TangentialModel::elastic_spring, false, tc / 4000);
  // Tolerance 0.5 %: the duration is counted in whole steps (0.025 % here), the rest is the
  // velocity Verlet error at 4000 steps per contact.
  EXPECT_NEAR(c.duration / tc, 1.0, 0.005);
  EXPECT_NEAR(c.restitution / e, 1.0, 0.005);
}

TEST(ContactCollision, ElasticSpringWallMatchesCollisionTimeAndRestitution) {
  const double tc = params::collision_time(2e5, 50, 1.0);  // against a wall m_ij = m
  const double e = params::restitution_from_collision(2e5, 50, 1.0);
  const Collision c = head_on(TangentialModel::elastic_spring, true, tc / 4000);
  EXPECT_NEAR(c.duration / tc, 1.0, 0.005);
  EXPECT_NEAR(c.restitution / e, 1.0, 0.005);
}

// With max(., 0) on the normal force (Huet et al. 2021, Eq. 5) the contact ends when the force
// vanishes, before the overlap does: compare with the closed-form damped oscillator.
TEST(ContactCollision, ClampedNormalForceMatchesClosedForm) {
  const double m = 0.5, k = 2e5, eta = 25;
  const double gamma = eta / (2 * m), omega = std::sqrt(k / m - gamma * gamma);
  auto force = [&](double t) {
    const double delta = std::exp(-gamma * t) * std::sin(omega * t) / omega;
    const double rate = std::exp(-gamma * t) * (std::cos(omega * t) - gamma / omega * std::sin(omega * t));
    return k * delta + eta * rate;
  };
  double lo = 0.5 * kPi / omega, hi = kPi / omega;  // the force changes sign in the second half
  for (int it = 0; it < 200; ++it) (force(0.5 * (lo + hi)) > 0 ? lo : hi) = 0.5 * (lo + hi);
  const double t_end = 0.5 * (lo + hi);
  const double e_clamped =
      -std::exp(-gamma * t_end) * (std::cos(omega * t_end) - gamma / omega * std::sin(omega * t_end));
  const double dt = params::collision_time(k, eta, m) / 4000;
  const Collision c = head_on(TangentialModel::memory, false, dt);
  EXPECT_NEAR(c.restitution / e_clamped, 1.0, 0.005);
  // After the force vanishes the spheres still overlap briefly and fly apart force-free.
  EXPECT_GT(c.duration, t_end);
}

// Two spheres graze each other, once straight through and once with a state capture and
// restore in the middle of the contact. When they separate the stored tangential spring and
// normal must be zero (a later contact starts afresh), and the restored run must transfer the
// same impulse as the straight one.
TEST(ContactCollision, EndedContactsForgetTheirMemory) {
  for (const TangentialModel model :
       {TangentialModel::elastic_spring, TangentialModel::memory, TangentialModel::memoryless}) {
    WorldSettings s;
    s.domain = {{-10, -10, -10}, {10, 10, 10}};
    s.gravity = {};
    s.time_step = 1e-4;
    s.tangential_model = model;
    s.skin = 2e-4;  // lists rebuilt every few steps, memories carried over each time
    const auto make = [&] {
      auto w = std::make_unique<World>(s);
      w->contacts().resize(1, 1);
      w->contacts().set_pair(0, 0, chute_params());
      ParticleInit a;
      a.radius = 0.5;
      a.mass = 1;
      a.inertia = {0.1, 0.1, 0.1};
      a.position = {-0.6, 0.1, 0};
      a.velocity = {0.5, 0.2, 0};
      w->add_particle(a);
      a.position = {0.6, -0.1, 0};
      a.velocity = {-0.5, -0.2, 0};
      w->add_particle(a);
      return w;
    };
    auto w = make();
    const auto memory_is_blank = [&](const World& world) {
      const WorldState st = const_cast<World&>(world).capture_state();
      for (const auto* v : {&st.pair_memory.spring, &st.pair_memory.normal_prev, &st.pair_memory.rolling})
        for (const Vec3& m : *v)
          if (m != Vec3{}) return false;
      return true;
    };
    const auto graze = [&](std::unique_ptr<World>& world, bool restore_midway) {
      const Vec3 v0 = world->particles().velocity[world->particles().gid[0] == 0 ? 0 : 1];
      bool touched = false;
      int steps = 0;
      for (int k = 0; k < 100000; ++k) {
        world->step();
        const bool touching = world->diagnostics().contacts > 0;
        if (touching && !touched && restore_midway) {
          // Mid-contact: carry the state into a fresh world, which rebuilds its lists.
          for (int m = 0; m < 5; ++m) world->step();
          const WorldState middle = world->capture_state();
          auto fresh = make();
          fresh->restore_state(middle);
          world = std::move(fresh);
        }
        touched = touched || touching;
        if (touching) ++steps;
        if (touched && !world->diagnostics().contacts) break;
      }
      EXPECT_GT(steps, 10);
      const Vec3 v1 = world->particles().velocity[world->particles().gid[0] == 0 ? 0 : 1];
      return v1 - v0;
    };
    const Vec3 restored = graze(w, true);
    EXPECT_TRUE(memory_is_blank(*w)) << "after the graze carried through a restore";
    auto plain = make();
    const Vec3 straight = graze(plain, false);
    EXPECT_TRUE(memory_is_blank(*plain)) << "after the graze";
    EXPECT_GT(norm(straight), 0.1);
    EXPECT_EQ(restored, straight);  // restores continue bit for bit
  }
}

TEST(ContactParameters, HuetProcedureRoundTrips) {
  // Eq. (16) then Eq. (13): the stiffness chosen for delta_max gives back delta_max.
  const double m = 0.5 * 2.5e3 * 4.0 / 3.0 * kPi * 1e-9;  // two 1 mm glass spheres (Table II)
  const double kn = params::normal_stiffness_for_overlap(m, 1.0, 0.005e-3, 0.45);
  EXPECT_NEAR(params::max_overlap(kn, m, 1.0, 0.45) / 0.005e-3, 1.0, 1e-12);
  // Eq. (17) into Eq. (11) gives back the restitution; Eq. (12) equals Weinhart's Eq. (5).
  const double eta = params::normal_damping(kn, m, 0.45);
  EXPECT_NEAR(params::restitution(kn, eta, m), 0.45, 1e-12);
  EXPECT_NEAR(params::contact_time(kn, m, 0.45), params::collision_time(kn, eta, m), 1e-15);
}

}  // namespace
}  // namespace talus
