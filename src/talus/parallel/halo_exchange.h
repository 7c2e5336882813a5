#pragma once
// Ghosts from the neighbouring sub-domain above (slab_decomposition.h). At a rebuild each rank
// sends the lower neighbour copies of its particles within one interaction range of its lower
// cut (owned ones and their periodic images along the other axes, so that corners come along),
// shifted by the box length where the cut is the periodic face; every step it sends their
// fresh state down (forward) and receives the forces its particles' copies took there, added
// to them before periodic images fold onto their owners (reverse). One rank along a periodic
// axis exchanges with itself: the periodic images along that axis.
#include <cstdint>
#include <vector>

#include "talus/body/particles.h"
#include "talus/collide/cell_grid.h"
#include "talus/parallel/slab_decomposition.h"

namespace talus {

class HaloExchange {
 public:
  // Sends the particles at [0, size) within `band` of the lower cut, appends those that
  // arrive from above as ghosts with their cells (the layer above the grid's last slab).
  void create(ParticleStore& particles, const SlabDecomposition& slabs, const CellGrid& grid, double band,
              std::vector<CellCoord>& cell_of);
  // Ghosts take their originals' positions, orientations and velocities; their forces are zeroed.
  void forward(ParticleStore& particles) const;
  // The originals receive the forces and torques their ghosts took.
  void reverse(ParticleStore& particles) const;

  std::size_t first() const { return first_; }  ///< index of the first ghost from above
  std::size_t count() const { return received_; }
  const std::vector<std::uint32_t>& sent_indices() const { return sent_index_; }  ///< sent down, owned or images

 private:
  const SlabDecomposition* slabs_ = nullptr;
  std::vector<std::uint32_t> sent_index_;  ///< the particles sent down, in message order
  double shift_ = 0;                       ///< m, added to the sent coordinate (the periodic face)
  std::size_t first_ = 0, received_ = 0;
  mutable std::vector<std::byte> out_, in_;  ///< the every-step messages, kept to spare the allocations
};

}  // namespace talus
