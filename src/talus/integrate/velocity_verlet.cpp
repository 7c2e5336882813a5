#include "talus/integrate/velocity_verlet.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#if defined(__AVX2__) && defined(__FMA__)
#include <immintrin.h>
#define TALUS_END_STEP_AVX2 1
#endif

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

// a + s b rounded the same way wherever it is written: the compiler may fuse a * and a + or
// not depending on the code around them, and the fused kicks of World::run must give the bits
// of separate ones. Where the CPU has a fused multiply-add, std::fma is that one instruction;
// where it has none the compiler cannot fuse either, and std::fma would be a call into libm
// that costs a tenth of a sphere step.
inline double fused(double s, double b, double a) {
#if defined(__FMA__) || defined(__ARM_FEATURE_FMA)
  return std::fma(s, b, a);
#else
  return s * b + a;
#endif
}

inline Vec3 fma(double s, const Vec3& b, const Vec3& a) { return {fused(s, b.x, a.x), fused(s, b.y, a.y), fused(s, b.z, a.z)}; }

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

namespace {
// A plain sphere's two half kicks and drift (kick_drift_one<2, true>, the same operations) on
// arrays the compiler knows apart, so that their addresses stay in registers across the stores;
// returns its squared distance from its position at the last build.
struct SphereArrays {
  Vec3* __restrict position;
  Vec3* __restrict velocity;
  Vec3* __restrict spin;
  const Vec3* __restrict force;
  const Vec3* __restrict torque;
  const Vec3* __restrict at_build;
};

[[gnu::always_inline]] inline double kick_kick_drift_sphere(const SphereArrays& a, std::size_t i, double inv_m,
                                                            double inv_moment, const StepEnd& e) {
  const Vec3 accel = fma(inv_m, a.force[i], e.gravity);  // F/m + g
  const double spin_gain = e.h * inv_moment;
  const Vec3 torque = a.torque[i];
  Vec3 v = a.velocity[i], w = a.spin[i];
  v = fma(e.h, accel, v);
  w = fma(spin_gain, torque, w);
  v = fma(e.h, accel, v);
  w = fma(spin_gain, torque, w);
  a.velocity[i] = v;
  a.spin[i] = w;
  const Vec3 x = fma(e.dt, v, a.position[i]);
  a.position[i] = x;
  const Vec3 d = x - a.at_build[i];
  return fused(d.z, d.z, fused(d.x, d.x, d.y * d.y));
}

// One particle's step end with a next step: the sphere path above for a plain sphere, else the
// general one; returns its squared drift from the last build.
[[gnu::always_inline]] inline double end_one(ParticleStore& p, const SphereArrays& a, std::size_t i, bool plain,
                                             const StepEnd& e) {
  if (!plain) return kick_drift_one<2, true>(p, i, e.h, e.dt, e.gravity, e.position_at_build);
  const double d2 = kick_kick_drift_sphere(a, i, p.inv_mass[i], p.inv_inertia[i].x, e);
  p.force[i] = {};
  p.torque[i] = {};
  return d2;
}
}  // namespace

bool is_plain_sphere(const ParticleStore& p, std::size_t i) {
  return p.inv_mass[i] != 0.0 && plain_sphere(p, i, p.inv_inertia[i]);
}

#ifdef TALUS_END_STEP_AVX2
namespace {
// Four plain spheres i .. i + 3 at once: their Vec3s are twelve consecutive doubles, three
// vectors whose lanes run x0 y0 z0 x1 | y1 z1 x2 y2 | z2 x3 y3 z3, so a per-particle factor
// is spread over the lanes by a fixed permutation. Each lane does what kick_kick_drift_sphere
// does to one component, with the same fused operations, so the bits are the same.
struct Lanes3 {
  __m256d a, b, c;
};
inline Lanes3 spread(__m256d per_particle) {
  return {_mm256_permute4x64_pd(per_particle, 0x40), _mm256_permute4x64_pd(per_particle, 0xA5),
          _mm256_permute4x64_pd(per_particle, 0xFE)};
}

__m256d kick_kick_drift_four(const SphereArrays& a, double* __restrict force, double* __restrict torque,
                             const double* __restrict inv_mass, const Vec3* __restrict inv_inertia, std::size_t i,
                             const Lanes3& gravity, const StepEnd& e) {
  const __m256d h = _mm256_set1_pd(e.h), dt = _mm256_set1_pd(e.dt);
  const Lanes3 inv_m = spread(_mm256_loadu_pd(inv_mass + i));
  const __m256d moments =
      _mm256_setr_pd(inv_inertia[i].x, inv_inertia[i + 1].x, inv_inertia[i + 2].x, inv_inertia[i + 3].x);
  const Lanes3 gain = spread(_mm256_mul_pd(h, moments));
  double* f = force + 3 * i;
  double* t = torque + 3 * i;
  double* v = &a.velocity[i].x;
  double* w = &a.spin[i].x;
  double* x = &a.position[i].x;
  const double* x0 = &a.at_build[i].x;
  __m256d d[3];
  const __m256d m[3] = {inv_m.a, inv_m.b, inv_m.c}, g[3] = {gravity.a, gravity.b, gravity.c};
  const __m256d s[3] = {gain.a, gain.b, gain.c};
  for (int k = 0; k < 3; ++k) {
    const __m256d accel = _mm256_fmadd_pd(m[k], _mm256_loadu_pd(f + 4 * k), g[k]);
    const __m256d tau = _mm256_loadu_pd(t + 4 * k);
    __m256d vk = _mm256_loadu_pd(v + 4 * k), wk = _mm256_loadu_pd(w + 4 * k);
    vk = _mm256_fmadd_pd(h, accel, vk);
    wk = _mm256_fmadd_pd(s[k], tau, wk);
    vk = _mm256_fmadd_pd(h, accel, vk);
    wk = _mm256_fmadd_pd(s[k], tau, wk);
    _mm256_storeu_pd(v + 4 * k, vk);
    _mm256_storeu_pd(w + 4 * k, wk);
    const __m256d xk = _mm256_fmadd_pd(dt, vk, _mm256_loadu_pd(x + 4 * k));
    _mm256_storeu_pd(x + 4 * k, xk);
    d[k] = _mm256_sub_pd(xk, _mm256_loadu_pd(x0 + 4 * k));
    _mm256_storeu_pd(f + 4 * k, _mm256_setzero_pd());
    _mm256_storeu_pd(t + 4 * k, _mm256_setzero_pd());
  }
  // The components of the four displacements, particle by particle.
  const __m256d dx = _mm256_permute4x64_pd(_mm256_blend_pd(_mm256_blend_pd(d[0], d[1], 0x4), d[2], 0x2), 0x6C);
  const __m256d dy = _mm256_permute4x64_pd(_mm256_blend_pd(_mm256_blend_pd(d[0], d[1], 0x9), d[2], 0x4), 0xB1);
  const __m256d dz = _mm256_permute4x64_pd(_mm256_blend_pd(_mm256_blend_pd(d[0], d[1], 0x2), d[2], 0x9), 0xC6);
  return _mm256_fmadd_pd(dz, dz, _mm256_fmadd_pd(dx, dx, _mm256_mul_pd(dy, dy)));
}
}  // namespace
#endif

double end_step(ParticleStore& p, std::size_t begin, std::size_t end, const StepEnd& e, const StepEndKind* kind) {
  double max_d2 = 0;
  if (!e.next_step) {
    for (std::size_t i = begin; i < end; ++i)
      if (kind[i] != StepEndKind::late) kick_drift_one<1, false>(p, i, e.h, e.dt, e.gravity, e.position_at_build);
    return max_d2;
  }
  const SphereArrays a{p.position.data(), p.velocity.data(), p.angular_velocity.data(),
                       p.force.data(),    p.torque.data(),   e.position_at_build};
  [[maybe_unused]] const double* __restrict inv_mass = p.inv_mass.data();
  [[maybe_unused]] const Vec3* __restrict inv_inertia = p.inv_inertia.data();
  [[maybe_unused]] Vec3* __restrict force = p.force.data();
  [[maybe_unused]] Vec3* __restrict torque = p.torque.data();
#ifdef TALUS_END_STEP_AVX2
  const Vec3& g = e.gravity;
  const Lanes3 gravity{_mm256_setr_pd(g.x, g.y, g.z, g.x), _mm256_setr_pd(g.y, g.z, g.x, g.y),
                       _mm256_setr_pd(g.z, g.x, g.y, g.z)};
  __m256d max4 = _mm256_setzero_pd();
  const auto four_plain = [&](std::size_t first) {
    std::uint32_t four;
    std::memcpy(&four, kind + first, 4);
    return four == 0;  // StepEndKind::plain_sphere is 0
  };
#endif
  for (std::size_t i = begin; i < end; ++i) {
#ifdef TALUS_END_STEP_AVX2
    for (; i + 4 <= end && four_plain(i); i += 4)
      max4 = _mm256_max_pd(max4, kick_kick_drift_four(a, &force[0].x, &torque[0].x, inv_mass, inv_inertia, i, gravity, e));
    if (i == end) break;
#endif
    if (kind[i] != StepEndKind::late) max_d2 = std::max(max_d2, end_one(p, a, i, kind[i] == StepEndKind::plain_sphere, e));
  }
#ifdef TALUS_END_STEP_AVX2
  alignas(32) double lanes[4];
  _mm256_store_pd(lanes, max4);
  for (const double l : lanes) max_d2 = std::max(max_d2, l);
#endif
  return max_d2;
}

double end_step_of(ParticleStore& p, std::size_t i, const StepEnd& e) {
  if (!e.next_step) {
    kick_drift_one<1, false>(p, i, e.h, e.dt, e.gravity, e.position_at_build);
    return 0.0;
  }
  const SphereArrays a{p.position.data(), p.velocity.data(), p.angular_velocity.data(),
                       p.force.data(),    p.torque.data(),   e.position_at_build};
  return end_one(p, a, i, is_plain_sphere(p, i), e);
}

double end_step(ParticleStore& p, const std::vector<std::uint32_t>& indices, const StepEnd& e) {
  double max_d2 = 0;
  if (!e.next_step) {
    for (const std::uint32_t i : indices) kick_drift_one<1, false>(p, i, e.h, e.dt, e.gravity, e.position_at_build);
    return max_d2;
  }
  const SphereArrays a{p.position.data(), p.velocity.data(), p.angular_velocity.data(),
                       p.force.data(),    p.torque.data(),   e.position_at_build};
  const long n = static_cast<long>(indices.size());
#pragma omp parallel for schedule(static) reduction(max : max_d2) if (worth_parallel_ghost_pass(indices.size()))
  for (long k = 0; k < n; ++k) {
    const std::uint32_t i = indices[k];
    max_d2 = std::max(max_d2, end_one(p, a, i, is_plain_sphere(p, i), e));
  }
  return max_d2;
}

double kick_drift(ParticleStore& p, int kicks, double h, double dt, const Vec3& gravity,
                  const std::vector<Vec3>& at_build, std::size_t cost) {
  return kicks == 2 ? kick_drift_pass<2>(p, h, dt, gravity, at_build, cost)
                    : kick_drift_pass<1>(p, h, dt, gravity, at_build, cost);
}

}  // namespace talus
