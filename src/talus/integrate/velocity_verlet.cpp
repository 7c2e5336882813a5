#include "talus/integrate/velocity_verlet.h"

#include <algorithm>
#include <cmath>

#include "talus/integrate/rigid_rotation.h"
#include "talus/world/parallel.h"

namespace talus {
namespace {
// Equal principal moments: omega and L are parallel and the free flow is a steady rotation.
inline bool isotropic(const Vec3& inv_i) { return inv_i.x == inv_i.y && inv_i.y == inv_i.z; }

// Rotation of a rigid body over dt: shaped isotropic bodies turn about omega, anisotropic ones
// follow the free rigid-body flow (which also turns omega). Kept out of line: spheres never
// come here, and the hot loops stay small.
[[gnu::noinline]] void turn_body(ParticleStore& p, std::size_t i, double dt) {
  const Vec3 inv_i = p.inv_inertia[i];
  Quat& q = p.orientation[i];
  if (isotropic(inv_i)) {
    // Free rotation of an isotropic body is a steady turn about omega.
    const Vec3 w = p.angular_velocity[i];
    const double angle = norm(w) * dt;
    if (angle > 0) q = (Quat::from_axis_angle(w, angle) * q).normalized();
  } else {
    Vec3 l = body_momentum(q, inv_i, p.angular_velocity[i]);
    free_rotation(q, l, inv_i, dt);
    p.angular_velocity[i] = world_angular_velocity(q, inv_i, l);
  }
}

// L += h tau at fixed orientation for an anisotropic body; the gyroscopic term is in the drift's free flow.
[[gnu::noinline]] void kick_anisotropic(ParticleStore& p, std::size_t i, double h) {
  const Quat& q = p.orientation[i];
  p.angular_velocity[i] += h * q.rotate(hadamard(p.inv_inertia[i], q.rotate_inverse(p.torque[i])));
}

// a + s b with one rounding, written out: the compiler may fuse a * and a + or not depending on
// the code around them, and the fused kicks of World::run must give the bits of separate ones.
inline Vec3 fma(double s, const Vec3& b, const Vec3& a) {
  return {std::fma(s, b.x, a.x), std::fma(s, b.y, a.y), std::fma(s, b.z, a.z)};
}

// A sphere: no orientation to track, and its spin takes the torque straight (equal moments).
inline bool plain_sphere(const ParticleStore& p, std::size_t i, const Vec3& inv_i) {
  return p.shape[i] == 0 && isotropic(inv_i);
}

// `kicks` half kicks of a plain sphere on the same force, on local copies (for all the
// compiler knows the arrays alias, and it would reload and store them at every kick).
template <int kKicks>
[[gnu::always_inline]] inline Vec3 kick_sphere(ParticleStore& p, std::size_t i, double inv_m, const Vec3& inv_i,
                                               double h, const Vec3& gravity) {
  const Vec3 accel = fma(inv_m, p.force[i], gravity);  // F/m + g
  const double spin_gain = h * inv_i.x;
  const Vec3 torque = p.torque[i];
  Vec3 v = p.velocity[i], w = p.angular_velocity[i];
  for (int k = 0; k < kKicks; ++k) {
    v = fma(h, accel, v);
    w = fma(spin_gain, torque, w);
  }
  p.velocity[i] = v;
  p.angular_velocity[i] = w;
  return v;
}

// One mobile particle's half kick: v += h (F/m + g), omega += h I^-1 tau.
[[gnu::always_inline]] inline void kick_one(ParticleStore& p, std::size_t i, double inv_m, double h,
                                            const Vec3& gravity) {
  p.velocity[i] += h * (inv_m * p.force[i] + gravity);
  const Vec3 inv_i = p.inv_inertia[i];
  if (isotropic(inv_i)) {
    p.angular_velocity[i] += (h * inv_i.x) * p.torque[i];
  } else {
    kick_anisotropic(p, i, h);
  }
}

// One mobile particle's drift; returns its squared distance from its position at the last build.
[[gnu::always_inline]] inline double drift_one(ParticleStore& p, std::size_t i, double dt, const Vec3& at_build) {
  p.position[i] += dt * p.velocity[i];
  // A sphere's orientation plays no part in its dynamics: only shaped bodies track it.
  if (p.shape[i] != 0 || !isotropic(p.inv_inertia[i])) turn_body(p, i, dt);
  return norm2(p.position[i] - at_build);
}
}  // namespace

void kick(ParticleStore& p, double h, const Vec3& gravity, std::size_t cost) {
  const std::size_t n = p.owned;
#pragma omp parallel for schedule(static) if (worth_parallel(n * cost))
  for (std::size_t i = 0; i < n; ++i) {
    const double inv_m = p.inv_mass[i];
    if (inv_m == 0.0) continue;  // fixed particles: infinite mass, unaffected by gravity
    const Vec3 inv_i = p.inv_inertia[i];
    if (plain_sphere(p, i, inv_i)) {
      kick_sphere<1>(p, i, inv_m, inv_i, h, gravity);
    } else {
      kick_one(p, i, inv_m, h, gravity);
    }
  }
}

double drift(ParticleStore& p, double dt, const std::vector<Vec3>& at_build, std::size_t cost) {
  const std::size_t n = p.owned;
  double max_d2 = 0;
#pragma omp parallel for schedule(static) reduction(max : max_d2) if (worth_parallel(n * cost))
  for (std::size_t i = 0; i < n; ++i) {
    if (p.inv_mass[i] == 0.0) continue;
    max_d2 = std::max(max_d2, drift_one(p, i, dt, at_build[i]));
  }
  return max_d2;
}

namespace {
// `kKicks` half kicks of particle i, then its drift (returning its squared distance from its
// position at the last build) and its forces zeroed, or, with kDrift false, the kick alone.
template <int kKicks, bool kDrift>
[[gnu::always_inline]] inline double kick_drift_one(ParticleStore& p, std::size_t i, double h, double dt,
                                                    const Vec3& gravity, const Vec3* at_build) {
  double d2 = 0;
  const double inv_m = p.inv_mass[i];
  if (inv_m != 0.0) {
    const Vec3 inv_i = p.inv_inertia[i];
    if (plain_sphere(p, i, inv_i)) {
      const Vec3 v = kick_sphere<kKicks>(p, i, inv_m, inv_i, h, gravity);
      if constexpr (kDrift) {
        const Vec3 x = fma(dt, v, p.position[i]);
        p.position[i] = x;
        d2 = norm2(x - at_build[i]);
      }
    } else {
      for (int k = 0; k < kKicks; ++k) kick_one(p, i, inv_m, h, gravity);
      if constexpr (kDrift) d2 = drift_one(p, i, dt, at_build[i]);
    }
  }
  if constexpr (kDrift) {
    p.force[i] = {};
    p.torque[i] = {};
  }
  return d2;
}

template <int kKicks>
double kick_drift_pass(ParticleStore& p, double h, double dt, const Vec3& gravity, const std::vector<Vec3>& at_build,
                       std::size_t cost) {
  const std::size_t n = p.owned;
  double max_d2 = 0;
#pragma omp parallel for schedule(static) reduction(max : max_d2) if (worth_parallel(n * cost))
  for (std::size_t i = 0; i < n; ++i)
    max_d2 = std::max(max_d2, kick_drift_one<kKicks, true>(p, i, h, dt, gravity, at_build.data()));
  return max_d2;
}
}  // namespace

double end_step(ParticleStore& p, std::size_t begin, std::size_t end, const StepEnd& e, const std::uint8_t* skip) {
  double max_d2 = 0;
  if (e.next_step) {
    for (std::size_t i = begin; i < end; ++i)
      if (!skip[i]) max_d2 = std::max(max_d2, kick_drift_one<2, true>(p, i, e.h, e.dt, e.gravity, e.position_at_build));
  } else {
    for (std::size_t i = begin; i < end; ++i)
      if (!skip[i]) kick_drift_one<1, false>(p, i, e.h, e.dt, e.gravity, e.position_at_build);
  }
  return max_d2;
}

double end_step(ParticleStore& p, const std::vector<std::uint32_t>& indices, const StepEnd& e) {
  double max_d2 = 0;
  for (const std::uint32_t i : indices)
    max_d2 = std::max(max_d2, e.next_step ? kick_drift_one<2, true>(p, i, e.h, e.dt, e.gravity, e.position_at_build)
                                          : kick_drift_one<1, false>(p, i, e.h, e.dt, e.gravity, e.position_at_build));
  return max_d2;
}

double kick_drift(ParticleStore& p, int kicks, double h, double dt, const Vec3& gravity,
                  const std::vector<Vec3>& at_build, std::size_t cost) {
  return kicks == 2 ? kick_drift_pass<2>(p, h, dt, gravity, at_build, cost)
                    : kick_drift_pass<1>(p, h, dt, gravity, at_build, cost);
}

}  // namespace talus
