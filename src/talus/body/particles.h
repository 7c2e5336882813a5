#pragma once
// Particle state as structure of arrays. Entries [0, owned) are the particles this rank owns;
// entries [owned, size) are ghost copies: periodic images, then, in a distributed world, the
// copies from other ranks (parallel/halo_exchange.h). Ghosts carry their owner's global id.
#include <cstdint>
#include <vector>

#include "talus/math/quat.h"
#include "talus/math/vec3.h"

namespace talus {

struct ParticleStore {
  // Hot state, read and written every step.
  std::vector<Vec3> position;          ///< m, centre of mass, world frame
  std::vector<Vec3> velocity;          ///< m/s
  std::vector<Vec3> angular_velocity;  ///< rad/s, world frame
  std::vector<Vec3> force;             ///< N, contact force accumulated this step
  std::vector<Vec3> torque;            ///< N m, about the centre of mass, world frame
  std::vector<Quat> orientation;       ///< body (principal) frame to world frame
  // Per-particle constants.
  std::vector<double> radius;          ///< m, bounding radius (the radius of a sphere)
  std::vector<double> inv_mass;        ///< 1/kg, zero for fixed particles
  std::vector<Vec3> inv_inertia;       ///< 1/(kg m^2), principal moments in the body frame; zero if fixed
  std::vector<double> mass;            ///< kg, nominal mass (also for fixed particles)
  std::vector<std::int32_t> species;   ///< index into the species table
  std::vector<std::int32_t> shape;     ///< index into the shape table (0: sphere)
  std::vector<std::uint32_t> gid;      ///< global id, stable for the whole run

  std::size_t owned = 0;  ///< number of owned particles; the rest are ghosts

  std::size_t size() const { return position.size(); }
  bool is_fixed(std::size_t i) const { return inv_mass[i] == 0.0; }

  void resize(std::size_t n);
  void reserve(std::size_t n);  ///< exact capacity, so that ghosts appended later do not double the arrays
  // Reorders the owned particles so that new index k holds old index order[k]; drops ghosts.
  void permute_owned(const std::vector<std::uint32_t>& order);
  // Appends ghost copies of the owned particles owner[g], shifted by shift[g], with zero force.
  void append_ghosts(const std::vector<std::uint32_t>& owner, const std::vector<Vec3>& shift);
  void drop_ghosts() { resize(owned); }
};

}  // namespace talus
