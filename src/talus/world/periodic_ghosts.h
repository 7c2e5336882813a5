#pragma once
// Periodic images as ghost particles: copies of owned particles near a periodic face, shifted
// by one box length. In a distributed world the images along the slab axis come from the halo
// exchange instead (parallel/halo_exchange.h), which sends these images along too.
#include <cstdint>
#include <vector>

#include "talus/body/particles.h"
#include "talus/collide/cell_grid.h"
#include "talus/world/domain.h"

namespace talus {

class PeriodicGhosts {
 public:
  // Appends ghosts of every particle within `band` of a periodic face (corners included) and
  // their cells (the owner's cell shifted by a whole box), except below the grid's first slab,
  // where the pair list never looks. Owned particles must be wrapped.
  void create(ParticleStore& particles, const Domain& domain, const CellGrid& grid, double band,
              std::vector<CellCoord>& cell_of);
  void update_positions(ParticleStore& particles) const;   ///< positions and orientations
  void update_velocities(ParticleStore& particles) const;  ///< velocities and angular velocities
  // Both updates in one pass, and ghost forces and torques reset for the next force pass.
  void refresh(ParticleStore& particles) const;
  void fold_forces(ParticleStore& particles) const;        ///< adds ghost forces to owners, each in ghost order
  // The same owner by owner: owners() distinct owners (ascending), owner_at(k) the k-th, whose
  // ghosts fold_into_owner(k) adds to it (as fold_forces does) and refresh_ghosts_of(k) sets
  // from its state (as refresh does). Different owners may be taken by different threads.
  std::size_t owners() const { return fold_owner_.size(); }
  std::uint32_t owner_at(std::size_t k) const { return fold_owner_[k]; }
  void fold_into_owner(ParticleStore& particles, std::size_t k) const;
  void refresh_ghosts_of(ParticleStore& particles, std::size_t k) const;
  // True if none of owner k's ghosts is shifted along `axis`: they share its cell layer there.
  bool ghosts_share_layer(std::size_t k, int axis) const;
  std::size_t count() const { return owner_.size(); }
  std::uint32_t owner(std::size_t ghost) const { return owner_[ghost]; }

 private:
  void group_by_owner(std::size_t owned);  ///< fills the fold_ arrays from owner_
  void refresh_ghost(ParticleStore& particles, std::size_t ghost) const;  ///< one ghost of refresh()

  std::vector<std::uint32_t> owner_;  ///< owned index of each ghost's original
  std::vector<Vec3> shift_;           ///< m, ghost position minus owner position
  // The ghosts grouped by owner (owners ascending, each one's ghosts in ghost order), so that
  // owners fold in parallel and each adds its ghosts in the order of a serial fold.
  std::vector<std::uint32_t> fold_owner_;  ///< distinct owners
  std::vector<std::uint32_t> fold_start_;  ///< per distinct owner, its first entry in fold_ghost_
  std::vector<std::uint32_t> fold_ghost_;  ///< ghost numbers
};

}  // namespace talus
