#include "talus/parallel/slab_decomposition.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace talus {

int SlabDecomposition::lower() const {
  if (rank() > 0) return rank() - 1;
  return periodic ? ranks() - 1 : -1;
}

int SlabDecomposition::upper() const {
  if (rank() + 1 < ranks()) return rank() + 1;
  return periodic ? 0 : -1;
}

int SlabDecomposition::owner_of(double x) const {
  const auto it = std::upper_bound(cut.begin() + 1, cut.end() - 1, x);
  return static_cast<int>(it - (cut.begin() + 1));
}

SlabDecomposition SlabDecomposition::balanced(const Communicator& comm, const Domain& domain, int axis,
                                              std::vector<double> coordinate, double min_width) {
  const int ranks = comm.size();
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const bool periodic = domain.periodic[axis];
  const double lo = periodic ? domain.lo[axis] : -kInf, hi = periodic ? domain.hi[axis] : kInf;
  std::sort(coordinate.begin(), coordinate.end());
  std::vector<double> cut(ranks + 1, lo);
  cut[ranks] = hi;
  const std::size_t n = coordinate.size();
  for (int r = 1; r < ranks; ++r) {
    // Halfway between the last particle of one share and the first of the next.
    const std::size_t k = n * r / ranks;
    cut[r] = n == 0 ? 0.0 : k == 0 ? coordinate[0] : 0.5 * (coordinate[k - 1] + coordinate[k]);
  }
  // A slab narrower than the interaction range would need ghosts from beyond its neighbour.
  for (int r = 1; r < ranks; ++r) cut[r] = std::max(cut[r], cut[r - 1] + min_width);
  for (int r = ranks - 1; r >= 1; --r) cut[r] = std::min(cut[r], cut[r + 1] - min_width);
  return with_cuts(comm, domain, axis, std::move(cut), min_width);
}

SlabDecomposition SlabDecomposition::with_cuts(const Communicator& comm, const Domain& domain, int axis,
                                               std::vector<double> cut, double min_width) {
  SlabDecomposition d;
  d.comm = &comm;
  d.axis = axis;
  d.periodic = domain.periodic[axis];
  d.length = domain.length(axis);
  d.cut = std::move(cut);
  const int ranks = comm.size();
  if (d.ranks() != ranks)
    throw std::runtime_error(std::to_string(d.cut.size()) + " cuts for " + std::to_string(ranks) +
                             " ranks: give one more cut than ranks");
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const double lo = d.periodic ? domain.lo[axis] : -kInf, hi = d.periodic ? domain.hi[axis] : kInf;
  if (d.cut.front() != lo || d.cut.back() != hi)
    throw std::runtime_error("the slabs must span axis " + std::to_string(axis) + " from end to end");
  for (int r = 0; r < ranks; ++r)
    if (!(d.cut[r + 1] - d.cut[r] >= min_width))
      throw std::runtime_error("slab " + std::to_string(r) + " along axis " + std::to_string(axis) +
                               " is narrower than the interaction range (" + std::to_string(min_width) +
                               " m): run on fewer ranks");
  return d;
}

}  // namespace talus
