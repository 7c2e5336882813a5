#pragma once
// Periodic images as ghost particles: copies of owned particles near a periodic face, shifted
// by one box length. The same mechanism will carry subdomain neighbours under MPI.
#include <cstdint>
#include <vector>

#include "talus/body/particles.h"
#include "talus/collide/cell_grid.h"
#include "talus/world/domain.h"

namespace talus {

class PeriodicGhosts {
 public:
  // Appends ghosts of every particle within `band` of a periodic face (corners included) and
  // their cells (the owner's cell shifted by a whole box). Owned particles must be wrapped.
  void create(ParticleStore& particles, const Domain& domain, const CellGrid& grid, double band,
              std::vector<CellCoord>& cell_of);
  void update_positions(ParticleStore& particles) const;   ///< positions and orientations
  void update_velocities(ParticleStore& particles) const;  ///< velocities and angular velocities
  // Both updates in one pass, and ghost forces and torques reset for the next force pass.
  void refresh(ParticleStore& particles) const;
  void fold_forces(ParticleStore& particles) const;        ///< adds ghost forces to owners, in ghost order
  std::size_t count() const { return owner_.size(); }
  std::uint32_t owner(std::size_t ghost) const { return owner_[ghost]; }

 private:
  std::vector<std::uint32_t> owner_;  ///< owned index of each ghost's original
  std::vector<Vec3> shift_;           ///< m, ghost position minus owner position
};

}  // namespace talus
