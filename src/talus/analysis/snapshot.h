#pragma once
// A self-contained picture of the system at one instant: what every analysis reads.
// The engine fills it (World::snapshot()); analyses never touch engine internals, so they
// run alike on a live simulation and on saved output.
#include <cstdint>
#include <vector>

#include "talus/math/quat.h"
#include "talus/math/vec3.h"

namespace talus {

struct ParticleRecord {
  std::uint32_t id = 0;        ///< global particle id, stable for the whole run
  int species = 0;             ///< index into the scenario's species table
  int shape = 0;               ///< index into the scenario's shape table (0: sphere)
  bool fixed = false;          ///< fixed particles have infinite mass and never move
  double mass = 0;             ///< kg (infinite for fixed particles: stored as their nominal mass)
  double radius = 0;           ///< m, bounding radius (the radius for spheres)
  double volume = 0;           ///< m^3
  Vec3 position;               ///< m, centre of mass
  Vec3 velocity;               ///< m/s
  Vec3 angular_velocity;       ///< rad/s, world frame
  Quat orientation;            ///< body to world rotation
};

// One contact point. For a particle-particle contact the force is the one that particle j
// exerts on particle i; for a wall contact j is -1 and `wall` names the wall.
struct ContactRecord {
  int i = -1;                  ///< index of the first particle in Snapshot::particles
  int j = -1;                  ///< index of the second particle, or -1 for a wall contact
  int wall = -1;               ///< wall index when j == -1
  Vec3 point;                  ///< m, contact point (midpoint of the overlap)
  Vec3 normal;                 ///< unit normal, pointing from j (or the wall) towards i
  Vec3 force;                  ///< N, total contact force on i
  double overlap = 0;          ///< m, normal overlap
};

struct Snapshot {
  double time = 0;                       ///< s
  Vec3 gravity;                          ///< m/s^2
  Vec3 domain_min, domain_max;           ///< m, the simulation box
  bool periodic[3] = {false, false, false};
  std::vector<ParticleRecord> particles;
  std::vector<ContactRecord> contacts;
};

}  // namespace talus
