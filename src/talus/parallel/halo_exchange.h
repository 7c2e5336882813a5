#pragma once
// Ghosts from the neighbouring sub-domains (rank_grid.h), made in stages, one per cut axis as
// in LAMMPS's comm: each stage sends copies of every particle held so far (owned ones, their
// periodic images along uncut axes, the copies of earlier stages) within one interaction range
// of a cut, so that edges and corners come along. Across the other cut axes a stage sends both
// ways; across the slab axis, last, it sends down only, and the copies from the rank above
// fill the layer of cells above the sub-domain. A copy sent across a periodic face is shifted
// by the box length.
//
// Every step the stages send their copies' fresh state in the same order (forward), and the
// forces the copies took go back in the reverse order (reverse), each added to what was sent,
// before periodic images fold onto their owners. One rank along a periodic axis makes its
// images there itself (periodic_ghosts.h).
#include <cstdint>
#include <vector>

#include "talus/body/particles.h"
#include "talus/collide/cell_grid.h"
#include "talus/parallel/rank_grid.h"

namespace talus {

class HaloExchange {
 public:
  // Appends the copies from the neighbours as ghosts, with their cells: along the axis they
  // came across, the layer past the grid's end on their side.
  // `oriented`: some bodies turn (shaped ones); spheres keep the orientation they had, so
  // their copies keep the one they were made with and the forward messages leave it out.
  void create(ParticleStore& particles, const RankGrid& ranks, const CellGrid& grid, double band,
              std::vector<CellCoord>& cell_of, bool oriented = true);
  // Ghosts take their originals' positions, orientations and velocities; their forces are zeroed.
  void forward(ParticleStore& particles) const;
  // The originals receive the forces and torques their ghosts took.
  void reverse(ParticleStore& particles) const;

  std::size_t first() const { return passes_.empty() ? 0 : passes_.front().first; }  ///< the first ghost from a rank
  std::size_t count() const;  ///< ghosts from other ranks (or, along a periodic axis of two ranks, from itself)
  // Everything that was copied to a neighbour: owned particles, images, copies of earlier stages.
  std::vector<std::uint32_t> sent_indices() const;

 private:
  // One message of a stage: copies of `sent` go to `to` (shifted by `shift` along `axis`),
  // and `received` copies come from `from`, appended from index `first`.
  struct Pass {
    int axis = 0, to = -1, from = -1, tag = 0;
    double shift = 0;
    std::vector<std::uint32_t> sent;
    std::size_t first = 0, received = 0;
  };
  const RankGrid* ranks_ = nullptr;
  bool oriented_ = true;
  std::vector<Pass> passes_;
  mutable std::vector<std::byte> out_, in_;  ///< the every-step messages, kept to spare the allocations
};

}  // namespace talus
