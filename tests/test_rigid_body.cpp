// Rotation of one rigid body through kick/drift in World::step order (half kick, drift, half
// kick), zero force: torque-free invariants, the intermediate-axis instability, the symmetric
// top's precession, and the unchanged sphere path.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "talus/body/particles.h"
#include "talus/integrate/velocity_verlet.h"

namespace talus {
namespace {

constexpr double kPi = std::numbers::pi;

struct OneBody {
  ParticleStore p;
  std::vector<Vec3> at_build{Vec3{}};
  Vec3 inertia;

  // inertia: principal moments (kg m^2); omega_body: angular velocity in the body frame (rad/s).
  OneBody(const Vec3& inInertia, const Vec3& omega_body, const Quat& q) : inertia(inInertia) {
    p.resize(1);
    p.owned = 1;
    p.mass[0] = 1;
    p.inv_mass[0] = 1;
    p.radius[0] = 1;
    p.inv_inertia[0] = {1 / inertia.x, 1 / inertia.y, 1 / inertia.z};
    p.orientation[0] = q;
    p.angular_velocity[0] = q.rotate(omega_body);
  }
  void step(double dt) {
    kick(p, 0.5 * dt, Vec3{});
    drift(p, dt, at_build);
    kick(p, 0.5 * dt, Vec3{});
  }
  Vec3 omega_body() const { return p.orientation[0].rotate_inverse(p.angular_velocity[0]); }
  Vec3 momentum_body() const { return hadamard(inertia, omega_body()); }
  Vec3 momentum_world() const { return p.orientation[0].rotate(momentum_body()); }
  double energy() const { return 0.5 * dot(omega_body(), momentum_body()); }
};

const Quat kTilted = Quat::from_axis_angle({1, 2, 3}, 0.7);

struct Drift {
  double energy = 0, momentum_norm = 0, momentum_vector = 0;  ///< max relative deviations
};

Drift torque_free_drift(const Vec3& omega_body) {
  OneBody b({1, 2, 3}, omega_body, kTilted);
  const double dt = 2 * kPi / norm(omega_body) / 100;
  const double e0 = b.energy();
  const Vec3 l0 = b.momentum_world();
  Drift d;
  for (int s = 0; s < 100000; ++s) {
    b.step(dt);
    const Vec3 l = b.momentum_world();
    d.energy = std::max(d.energy, std::abs(b.energy() - e0) / e0);
    d.momentum_norm = std::max(d.momentum_norm, std::abs(norm(l) - norm(l0)) / norm(l0));
    d.momentum_vector = std::max(d.momentum_vector, norm(l - l0) / norm(l0));
  }
  return d;
}

TEST(RigidBody, TorqueFreeAsymmetricBodyConservesEnergyAndMomentum) {
  for (const Vec3& w : {Vec3{1, 0.01, -0.01}, Vec3{0.01, -0.01, 1}}) {  // minor axis, major axis
    const Drift d = torque_free_drift(w);
    std::printf("omega_b (%g %g %g): dE/E %.2e  d|L|/|L| %.2e  |dL|/|L| %.2e over 1e5 steps\n", w.x, w.y, w.z,
                d.energy, d.momentum_norm, d.momentum_vector);
    EXPECT_LT(d.energy, 1e-6);
    EXPECT_LT(d.momentum_norm, 1e-6);
    EXPECT_LT(d.momentum_vector, 1e-6);
  }
}

// Largest |omega_perp| / |omega| about body axis k over `periods` periods, and the time (in
// periods) at which omega_k first changed sign (infinity if it never did).
struct Spin {
  double max_off_axis = 0;
  double flip_period = INFINITY;
};

Spin spin_about(int k, double periods) {
  Vec3 w{1e-4, 1e-4, 1e-4};
  w[k] = 1;
  OneBody b({1, 2, 3}, w, kTilted);
  const double dt = 2 * kPi / 100;
  Spin s;
  for (int n = 1; n <= static_cast<int>(periods * 100); ++n) {
    b.step(dt);
    const Vec3 wb = b.omega_body();
    s.max_off_axis = std::max(s.max_off_axis, std::sqrt(norm2(wb) - wb[k] * wb[k]) / norm(wb));
    if (wb[k] < 0 && s.flip_period == INFINITY) s.flip_period = n / 100.0;
  }
  return s;
}

TEST(RigidBody, IntermediateAxisFlipsWhileMajorAndMinorAxesAreStable) {
  const Spin minor = spin_about(0, 40), middle = spin_about(1, 40), major = spin_about(2, 40);
  std::printf("off-axis over 40 periods: minor %.2e, major %.2e; intermediate flips after %.2f periods\n",
              minor.max_off_axis, major.max_off_axis, middle.flip_period);
  EXPECT_LT(middle.flip_period, 40);
  EXPECT_GT(middle.max_off_axis, 0.9);
  EXPECT_LT(minor.max_off_axis, 0.03);
  EXPECT_LT(major.max_off_axis, 0.03);
  EXPECT_EQ(minor.flip_period, INFINITY);
  EXPECT_EQ(major.flip_period, INFINITY);
}

// The isotropic path: omega = omega0 + tau t / I. A sphere (shape 0) keeps its orientation, which
// plays no part in its dynamics; the reference is recomputed here and -march=native lets the
// compiler fuse multiply-adds differently in the two translation units, so agreement is to a
// few ulp rather than bit for bit.
TEST(RigidBody, SpherePathIsUnchanged) {
  const Vec3 torque{0.3, -0.2, 0.5}, w0{1, -2, 0.5};
  const double inertia = 0.5, dt = 1e-3;
  OneBody b({inertia, inertia, inertia}, w0, kTilted);
  b.p.torque[0] = torque;
  const Vec3 w_start = kTilted.rotate(w0);
  Vec3 w = w_start;
  Quat q = kTilted;
  const int steps = 1000;
  for (int s = 0; s < steps; ++s) {
    b.step(dt);
    w += (0.5 * dt * (1 / inertia)) * torque;
    w += (0.5 * dt * (1 / inertia)) * torque;
  }
  const Vec3 exact = w_start + (steps * dt / inertia) * torque;  // omega0 + tau / I t
  const Vec3 got = b.p.angular_velocity[0];
  const Quat& got_q = b.p.orientation[0];
  std::printf("sphere: |omega - (omega0 + tau t / I)| = %.1e, |omega - old| = %.1e, |q - old| = %.1e\n",
              norm(got - exact), norm(got - w),
              std::sqrt((got_q.w - q.w) * (got_q.w - q.w) + norm2(got_q.vec() - q.vec())));
  EXPECT_LT(norm(got - exact), 1e-12 * norm(exact));  // round-off of 2000 sums
  EXPECT_LT(norm(got - w), 1e-14 * norm(w));
  EXPECT_NEAR(got_q.w, q.w, 1e-14);
  EXPECT_NEAR(got_q.x, q.x, 1e-14);
  EXPECT_NEAR(got_q.y, q.y, 1e-14);
  EXPECT_NEAR(got_q.z, q.z, 1e-14);
}

// Body-frame precession rate of omega_perp about the symmetry axis e_z, from the unwrapped
// phase of (omega_x, omega_y) over the run.
double precession_rate(const Vec3& inertia, const Vec3& omega_body, double dt, double duration) {
  OneBody b(inertia, omega_body, kTilted);
  double phase = 0, last = std::atan2(omega_body.y, omega_body.x);
  const int steps = static_cast<int>(std::lround(duration / dt));
  for (int s = 0; s < steps; ++s) {
    b.step(dt);
    const Vec3 wb = b.omega_body();
    const double now = std::atan2(wb.y, wb.x);
    phase += std::remainder(now - last, 2 * kPi);
    last = now;
  }
  return phase / (steps * dt);
}

TEST(RigidBody, SymmetricTopPrecessesAtAnalyticRate) {
  const Vec3 w{0.3, 0.1, 1};
  for (const Vec3& inertia : {Vec3{1, 1, 2}, Vec3{2, 2, 1}}) {  // oblate, prolate
    const double expected = (inertia.z - inertia.x) / inertia.x * w.z;  // Omega = (I3 - I1) / I1 w3
    const double period = 2 * kPi / norm(w);
    const double measured = precession_rate(inertia, w, period / 100, 2 * kPi / std::abs(expected) * 20);
    std::printf("I (%g %g %g): Omega %.8f, analytic %.8f, rel. error %.2e\n", inertia.x, inertia.y, inertia.z,
                measured, expected, std::abs(measured / expected - 1));
    EXPECT_NEAR(measured / expected, 1, 1e-4);
  }
}

}  // namespace
}  // namespace talus
