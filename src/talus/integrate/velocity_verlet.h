#pragma once
// Velocity Verlet for translation and rotation (Weinhart et al. 2012, Appendix C, Alg. 1):
// half kick, drift, forces, half kick. Spheres (equal principal moments) turn with omega;
// anisotropic bodies kick the angular momentum and drift by a splitting of the free rigid body
// (rigid_rotation.h), so the gyroscopic term lives in the drift.
#include <cstddef>
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

}  // namespace talus
