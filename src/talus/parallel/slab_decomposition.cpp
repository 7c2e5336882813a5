#include "talus/parallel/slab_decomposition.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace talus {

int SlabDecomposition::lower() const {
  if (index > 0) return index - 1;
  return periodic ? slabs() - 1 : -1;
}

int SlabDecomposition::upper() const {
  if (index + 1 < slabs()) return index + 1;
  return periodic ? 0 : -1;
}

int SlabDecomposition::owner_of(double x) const {
  const auto it = std::upper_bound(cut.begin() + 1, cut.end() - 1, x);
  return static_cast<int>(it - (cut.begin() + 1));
}

SlabDecomposition SlabDecomposition::whole(const Domain& domain, int axis) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const bool periodic = domain.periodic[axis];
  return with_cuts(domain, axis, {periodic ? domain.lo[axis] : -kInf, periodic ? domain.hi[axis] : kInf}, 0.0);
}

SlabDecomposition SlabDecomposition::balanced(const Domain& domain, int axis, int ranks,
                                              std::vector<double> coordinate, double min_width) {
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
  SlabDecomposition d = with_cuts(domain, axis, std::move(cut), min_width);
  d.rebalance = ranks > 1;
  return d;
}

SlabDecomposition SlabDecomposition::with_cuts(const Domain& domain, int axis, std::vector<double> cut,
                                               double min_width) {
  SlabDecomposition d;
  d.axis = axis;
  d.periodic = domain.periodic[axis];
  d.length = domain.length(axis);
  d.cut = std::move(cut);
  d.min_width = min_width;
  const int ranks = d.slabs();
  if (ranks < 1) throw std::runtime_error("a slab needs two cuts");
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

bool SlabDecomposition::move_cuts(const Communicator& comm, const std::vector<double>& coordinate,
                                  const std::vector<double>& weight, double tolerance) {
  const int n_ranks = slabs();
  if (!rebalance || n_ranks < 2) return false;
  const auto weight_of = [&](std::size_t i) { return weight.empty() ? 1.0 : weight[i]; };
  double owned = 0;
  for (std::size_t i = 0; i < coordinate.size(); ++i) owned += weight_of(i);
  const double total = comm.sum(owned);
  if (!(comm.max(owned) > tolerance * total / comm.size())) return false;
  // A histogram of all particles' weights along the axis, the same on every rank (weights are
  // whole numbers, whose sums are exact), and cuts at its quantiles.
  double lo = cut.front(), hi = cut.back();
  if (!periodic) {
    double mn = std::numeric_limits<double>::infinity(), mx = -mn;
    for (const double x : coordinate) mn = std::min(mn, x), mx = std::max(mx, x);
    lo = -comm.max(-mn);
    hi = comm.max(mx);
  }
  if (!(hi > lo)) return false;
  constexpr int kBins = 4096;
  std::vector<double> histogram(kBins, 0.0);
  const double width = (hi - lo) / kBins;
  for (std::size_t i = 0; i < coordinate.size(); ++i)
    histogram[std::clamp(static_cast<int>((coordinate[i] - lo) / width), 0, kBins - 1)] += weight_of(i);
  comm.sum_in_place(histogram);
  std::vector<double> next = cut;
  double below = 0;
  int bin = 0;
  for (int r = 1; r < n_ranks; ++r) {
    const double share = total * r / n_ranks;
    while (bin < kBins && below + histogram[bin] < share) below += histogram[bin++];
    next[r] = lo + width * bin;
  }
  // Each cut strictly between its neighbours' old places and the slabs no narrower than the
  // interaction range; where that cannot be, the cut stays.
  bool moved = false;
  for (int r = 1; r < n_ranks; ++r) {
    const double low = std::max(cut[r - 1], next[r - 1]) + min_width, high = cut[r + 1] - min_width;
    const double c = std::clamp(next[r], low, high);
    if (!(low <= high) || c == cut[r]) {
      next[r] = cut[r];
      continue;
    }
    next[r] = c;
    moved = true;
  }
  cut = next;
  return moved;
}

}  // namespace talus
