#pragma once
// Velocity Verlet for translation and rotation (Weinhart et al. 2012, Appendix C, Alg. 1):
// half kick, drift, forces, half kick.
#include <vector>

#include "talus/body/particles.h"

namespace talus {

// v += h (F/m + g), omega += h I^-1 (tau - omega x I omega) for every owned mobile particle.
void kick(ParticleStore& particles, double h, const Vec3& gravity);

// x += dt v and q advanced by the angular velocity; returns the largest squared distance of an
// owned particle from its position at the last neighbour-list build.
double drift(ParticleStore& particles, double dt, const std::vector<Vec3>& position_at_build);

}  // namespace talus
