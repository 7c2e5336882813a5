#pragma once
// Particle states that no valid time step leads to, found by one cheap pass over the owned
// particles (the run loop's blow-up guard, scenario/blowup_guard.h, calls it after every batch of
// steps). A particle is faulty when
//   - its position, velocity, angular velocity or force is NaN or infinite;
//   - it moves more than its own (bounding) radius in one step, |v| dt > r, or turns more than
//     a radian, |omega| dt > 1 (its surface then moves more than r);
//   - its centre lies more than its radius beyond a non-periodic face of the domain: the whole
//     particle has left the box.
// Why these limits: the loader keeps dt below t_c / 10, and an impact at speed v compresses a
// linear contact by about v t_c / pi. At |v| dt = r that is at least 10 r / pi, three radii: two
// such particles would pass through each other, so no contact at that speed is resolved and the
// state is already broken. A legitimate flow is orders of magnitude slower (the chute of
// Weinhart et al. 2012 moves about 1e-3 r per step, a dam break of 1 mm beads at 3 m/s with
// dt = 1e-5 s about 3e-2 r). A particle resting on a wall at the domain's face has its centre
// inside the box, and one overlapping the face keeps part of itself inside, so the tolerance
// of one radius never flags a particle in contact with the box; rough bases of fixed spheres
// that reach below the domain's floor (the chute's) keep their centres inside too.
#include <cstdint>
#include <vector>

#include "talus/body/particles.h"
#include "talus/world/domain.h"

namespace talus {

// What is wrong with a particle, as bits: a particle may have several.
enum StateFault : unsigned {
  kNotFinite = 1u,  ///< position, velocity, angular velocity or force is NaN or infinite
  kTooFast = 2u,    ///< |v| dt > radius
  kSpinning = 4u,   ///< |omega| dt > 1 rad
  kOutside = 8u,    ///< centre more than a radius beyond a non-periodic face of the domain
};

// The faces a particle's centre must stay within (one radius beyond them at most); infinite
// along periodic axes, where positions wrap.
struct GuardBounds {
  Vec3 lo, hi;       ///< m
  double dt2 = 0;    ///< s^2, the time step squared
  GuardBounds(const Domain& domain, double time_step);
};

// The faults of owned particle i (0 for a sound one).
inline unsigned particle_faults(const ParticleStore& p, std::size_t i, const GuardBounds& b) {
  const Vec3 x = p.position[i], v = p.velocity[i], w = p.angular_velocity[i], f = p.force[i];
  // x - x is 0 for a finite x and NaN for NaN or an infinity, so the sum is 0 exactly when all
  // twelve numbers are finite (the compiler may not fold x - x: NaNs are not ruled out).
  const double finite_test = (x.x - x.x) + (x.y - x.y) + (x.z - x.z) + (v.x - v.x) + (v.y - v.y) + (v.z - v.z) +
                             (w.x - w.x) + (w.y - w.y) + (w.z - w.z) + (f.x - f.x) + (f.y - f.y) + (f.z - f.z);
  const double r = p.radius[i];
  unsigned faults = finite_test == 0 ? 0u : kNotFinite;
  if (norm2(v) * b.dt2 > r * r) faults |= kTooFast;  // an overflowing norm2 counts as too fast
  if (norm2(w) * b.dt2 > 1) faults |= kSpinning;
  if (x.x < b.lo.x - r || x.y < b.lo.y - r || x.z < b.lo.z - r || x.x > b.hi.x + r || x.y > b.hi.y + r ||
      x.z > b.hi.z + r)
    faults |= kOutside;
  return faults;
}

// The faults of all owned particles OR-ed together: 0 when the state is sound. One pass, in
// parallel for large worlds, over the arrays the step itself streams through.
unsigned scan_state(const ParticleStore& particles, const Domain& domain, double time_step);

// The owned indices, in index order, of the particles with `fault` among their faults.
std::vector<std::uint32_t> particles_with(const ParticleStore& particles, const Domain& domain, double time_step,
                                          StateFault fault);

}  // namespace talus
