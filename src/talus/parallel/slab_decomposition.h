#pragma once
// A run spread over ranks as slabs along one axis: rank r owns the particles whose coordinate
// along `axis` lies in [cut[r], cut[r + 1]). The axis is the pair list's slab axis in every
// rank's grid, so that the ghosts from the rank above fill the one layer of cells above the
// sub-domain, where rows always list them (pair_list.h): each pair across a cut is computed
// once, by the lower rank, and its force on the ghost goes back to the owner (the half-shell
// scheme of LAMMPS's newton on).
#include <vector>

#include "talus/parallel/communicator.h"
#include "talus/world/domain.h"

namespace talus {

struct SlabDecomposition {
  const Communicator* comm = nullptr;
  int axis = 0;
  std::vector<double> cut;  ///< m, size() + 1 values; -inf and +inf at the ends of a non-periodic axis
  bool periodic = false;    ///< the axis is periodic: rank 0's lower neighbour is the last rank
  double length = 0;        ///< m, the box's length along a periodic axis
  double min_width = 0;     ///< m, the interaction range: no slab is narrower
  bool rebalance = false;   ///< the cuts follow the particles (rebalance_by_count)

  int ranks() const { return static_cast<int>(cut.size()) - 1; }
  int rank() const { return comm->rank(); }
  double lo() const { return cut[rank()]; }
  double hi() const { return cut[rank() + 1]; }
  // Neighbour ranks below and above (-1: none, at the ends of a non-periodic axis).
  int lower() const;
  int upper() const;
  int owner_of(double x) const;  ///< the rank whose slab holds coordinate x (wrapped)

  // Cuts that give every rank the same number of the particles at `coordinate` (the whole
  // system, known to every rank at the start), each slab at least `min_width` wide; they
  // follow the particles later (rebalance = true).
  static SlabDecomposition balanced(const Communicator& comm, const Domain& domain, int axis,
                                    std::vector<double> coordinate, double min_width);
  // The slabs [cut[r], cut[r + 1]) given, one per rank: ascending, at least `min_width` wide,
  // from face to face of a periodic axis (from -inf to +inf along another). They stay.
  static SlabDecomposition with_cuts(const Communicator& comm, const Domain& domain, int axis,
                                     std::vector<double> cut, double min_width);

  // Moves the cuts towards equal particle counts when the fullest rank holds more than
  // `tolerance` times the mean (collective; `coordinate` of this rank's particles). Each cut
  // stays strictly between its neighbours' old places, so a particle changes rank by one slab
  // at most (migrate), and repeated rebuilds converge. Returns whether the cuts moved.
  bool rebalance_by_count(const std::vector<double>& coordinate, double tolerance = 1.1);
};

}  // namespace talus
