#pragma once
// One axis of a grid of ranks (rank_grid.h), cut into slabs: the ranks whose slab index along
// `axis` is s own the particles whose coordinate lies in [cut[s], cut[s + 1]). An axis that
// is not cut has one slab from end to end.
#include <vector>

#include "talus/parallel/communicator.h"
#include "talus/world/domain.h"

namespace talus {

struct SlabDecomposition {
  int axis = 0;
  std::vector<double> cut = {0, 0};  ///< m, slabs() + 1 values; -inf and +inf at the ends of a non-periodic axis
  int index = 0;             ///< this rank's slab
  bool periodic = false;     ///< the axis is periodic: slab 0's lower neighbour is the last slab
  double length = 0;         ///< m, the box's length along a periodic axis
  double min_width = 0;      ///< m, the interaction range: no slab is narrower
  bool rebalance = false;    ///< the cuts follow the particles (move_cuts)

  int slabs() const { return static_cast<int>(cut.size()) - 1; }
  bool split() const { return slabs() > 1; }
  double lo() const { return cut[index]; }
  double hi() const { return cut[index + 1]; }
  // Neighbour slabs below and above (-1: none, at the ends of a non-periodic axis).
  int lower() const;
  int upper() const;
  int owner_of(double x) const;  ///< the slab that holds coordinate x (wrapped)

  // One slab from end to end.
  static SlabDecomposition whole(const Domain& domain, int axis);
  // `slabs` slabs with the same number of the particles at `coordinate` (the whole system,
  // known to every rank at the start), each at least `min_width` wide; they follow the
  // particles later (rebalance = true).
  static SlabDecomposition balanced(const Domain& domain, int axis, int slabs, std::vector<double> coordinate,
                                    double min_width);
  // The slabs [cut[s], cut[s + 1]) given: ascending, at least `min_width` wide, from face to
  // face of a periodic axis (from -inf to +inf along another). They stay.
  static SlabDecomposition with_cuts(const Domain& domain, int axis, std::vector<double> cut, double min_width);

  // Moves the cuts towards equal shares of the particles' weights (`weight`, one per particle,
  // or empty: each counts 1) when the heaviest rank holds more than `tolerance` times the mean
  // (collective over `comm`; `coordinate` of this rank's particles). Each cut stays strictly
  // between its neighbours' old places, so a particle changes slab by one at most (migrate),
  // and repeated rebuilds converge. Returns whether the cuts moved.
  bool move_cuts(const Communicator& comm, const std::vector<double>& coordinate, const std::vector<double>& weight,
                 double tolerance = 1.1);
};

}  // namespace talus
