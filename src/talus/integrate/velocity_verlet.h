#pragma once
// Velocity Verlet for translation and rotation (Weinhart et al. 2012, Appendix C, Alg. 1):
// half kick, drift, forces, half kick. Spheres (equal principal moments) turn with omega;
// anisotropic bodies kick the angular momentum and drift by a splitting of the free rigid body
// (rigid_rotation.h), so the gyroscopic term lives in the drift.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "talus/body/particles.h"

namespace talus {

// Each pass runs on the OpenMP team once particles times `cost` (the work of one particle, in
// sphere updates: a rigid body's turn costs some 16) reaches kParallelThreshold.

// v += h (F/m + g) and L += h tau, i.e. omega += h R I^-1 R^T tau, for every owned mobile particle.
void kick(ParticleStore& particles, double h, const Vec3& gravity, std::size_t cost = 1);

// x += dt v; q advanced by omega (spheres) or by the free rigid-body flow, which also turns
// omega (anisotropic bodies); returns the largest squared distance of an
// owned particle from its position at the last neighbour-list build.
double drift(ParticleStore& particles, double dt, const std::vector<Vec3>& position_at_build, std::size_t cost = 1);

// `kicks` times kick(h) (1, or 2 to end the last step and start this one on the same forces),
// then drift(dt), in one pass over the particles: the same arithmetic as separate passes, one
// sweep of memory instead of several. Force and torque of every owned particle are reset to
// zero for the next force pass. Returns what drift returns.
double kick_drift(ParticleStore& particles, int kicks, double h, double dt, const Vec3& gravity,
                  const std::vector<Vec3>& position_at_build, std::size_t cost = 1);

// How a particle's step ends once its force is complete: the closing half kick and, when
// another step follows, the next one's opening half kick and drift, its force and torque then
// zeroed (what kick_drift does with two kicks). World::run ends each particle's step as soon as
// nothing more can add to its force, while its data is still in cache.
struct StepEnd {
  bool next_step = false;
  double h = 0, dt = 0;  ///< s, half step and step
  Vec3 gravity;
  const Vec3* position_at_build = nullptr;
};

// Mobile, of shape 0 and equal principal moments: a particle the sphere paths integrate.
bool is_plain_sphere(const ParticleStore& particles, std::size_t i);

// How end_step takes each particle of a range (World keeps one per owned particle).
enum class StepEndKind : std::uint8_t {
  plain_sphere = 0,  ///< mobile, shape 0, equal moments: the fast path, four at a time
  late = 1,          ///< skipped: its force is not complete yet (ended from a list later)
  other = 2,         ///< fixed particles and rigid bodies: the general path
};
// Ends the step of owned particles [begin, end) but the late ones; returns the largest squared
// distance of a drifted particle from its position at the last build (0 without drift).
double end_step(ParticleStore& particles, std::size_t begin, std::size_t end, const StepEnd& how,
                const StepEndKind* kind);
// The same for the listed particles.
double end_step(ParticleStore& particles, const std::vector<std::uint32_t>& indices, const StepEnd& how);
// The same for particle i alone; returns its squared distance from its position at the last build.
double end_step_of(ParticleStore& particles, std::size_t i, const StepEnd& how);

}  // namespace talus
