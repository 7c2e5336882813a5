#pragma once
// A run spread over a grid of ranks, px x py x pz: each axis is cut into slabs
// (slab_decomposition.h) and the rank at slab indices (ix, iy, iz) owns the box where its three
// slabs cross, as LAMMPS's processor grid with cuts shifted per dimension ("balance shift").
//
// The halo is the one of LAMMPS's newton-on half lists, staged axis by axis so that corners
// come along (halo_exchange.h): across the cut axes other than `slab_axis` a rank receives
// copies from both neighbours, and across `slab_axis`, the pair list's slab axis, from the
// rank above only, with all the copies that rank holds. Each pair across a cut is then
// computed once: by the lower rank along the slab axis, and within one layer of cells along
// it by the rank owning the particle of lower global id (pair_list.h orders pairs that way).
#include <array>
#include <span>
#include <vector>

#include "talus/math/vec3.h"
#include "talus/parallel/communicator.h"
#include "talus/parallel/slab_decomposition.h"
#include "talus/world/domain.h"

namespace talus {

using RankCounts = std::array<int, 3>;  ///< ranks along x, y and z

struct RankGrid {
  const Communicator* comm = nullptr;
  std::array<SlabDecomposition, 3> axes;  ///< along x, y and z
  int slab_axis = 0;                      ///< a cut axis (x when none is)

  RankCounts counts() const { return {axes[0].slabs(), axes[1].slabs(), axes[2].slabs()}; }
  int rank_at(const std::array<int, 3>& index) const;  ///< x slowest, z fastest
  // The rank one slab away along `axis` (step -1 or +1), or -1 past a non-periodic end.
  int neighbour(int axis, int step) const;
  bool owns(const Vec3& wrapped) const;  ///< this rank's box holds the (wrapped) position
  // The cut axes in the order of the halo's stages: the others first, the slab axis last.
  std::vector<int> stage_axes() const;
  // Moves each cut axis's cuts towards the quantiles of the particles' weights along it when
  // the heaviest rank holds more than `tolerance` times the mean (collective; `weight` one per
  // owned particle, whole numbers, or empty for counts). Returns whether any moved.
  bool rebalance(std::span<const Vec3> owned_positions, const std::vector<double>& weight, double tolerance = 1.1);
  // What the cuts balance: particle counts, or the work of each particle's contacts (1 plus
  // the pair and wall entries its rows hold, LAMMPS's "weight neigh").
  enum class Balance { count, neighbours };
  Balance balance = Balance::count;

  // Cuts at the particles' quantiles along each axis (every rank passes the whole system),
  // `counts` ranks along the axes (their product the communicator's size).
  static RankGrid balanced(const Communicator& comm, const Domain& domain, const RankCounts& counts,
                           const std::vector<Vec3>& positions, double min_width, int slab_axis);
  // Slabs along one axis, at the cuts given (one more than ranks).
  static RankGrid slabs(const Communicator& comm, const Domain& domain, int axis, std::vector<double> cut,
                        double min_width);
  // The grid of the given cuts per axis (one slab where an axis holds two values).
  static RankGrid with_cuts(const Communicator& comm, const Domain& domain, std::array<std::vector<double>, 3> cut,
                            double min_width, int slab_axis);

  // The counts for `ranks` ranks when the user names none: slabs along `preferred` (the axis
  // whose layers of cells hold the particles most evenly) while each stays four interaction
  // ranges wide, where halos are a small share of a slab; past that, the grid whose sub-domain
  // faces have the least area, as LAMMPS's default processor grid, among those whose slabs
  // are at least one range wide. `extent` is the box, or the particles' span along a
  // non-periodic axis; `periodic` says which faces wrap (they count as cuts too).
  static RankCounts choose_counts(int ranks, const Vec3& extent, const std::array<bool, 3>& periodic,
                                  double range, int preferred);

 private:
  void place_rank();  ///< sets each axis's index from comm's rank
};

}  // namespace talus
