#include "talus/parallel/rank_grid.h"

#include <limits>
#include <stdexcept>
#include <string>

namespace talus {

int RankGrid::rank_at(const std::array<int, 3>& index) const {
  return (index[0] * axes[1].slabs() + index[1]) * axes[2].slabs() + index[2];
}

int RankGrid::neighbour(int axis, int step) const {
  const SlabDecomposition& a = axes[axis];
  const int slab = step < 0 ? a.lower() : a.upper();
  if (slab < 0) return -1;
  std::array<int, 3> index{axes[0].index, axes[1].index, axes[2].index};
  index[axis] = slab;
  return rank_at(index);
}

bool RankGrid::owns(const Vec3& wrapped) const {
  for (int a = 0; a < 3; ++a)
    if (axes[a].owner_of(wrapped[a]) != axes[a].index) return false;
  return true;
}

std::vector<int> RankGrid::stage_axes() const {
  std::vector<int> order;
  for (int a = 0; a < 3; ++a)
    if (a != slab_axis && axes[a].split()) order.push_back(a);
  if (axes[slab_axis].split()) order.push_back(slab_axis);
  return order;
}

bool RankGrid::rebalance(std::span<const Vec3> owned_positions, const std::vector<double>& weight, double tolerance) {
  bool moved = false;
  std::vector<double> coordinate(owned_positions.size());
  for (int a = 0; a < 3; ++a) {
    if (!axes[a].split() || !axes[a].rebalance) continue;
    for (std::size_t i = 0; i < owned_positions.size(); ++i) coordinate[i] = owned_positions[i][a];
    moved |= axes[a].move_cuts(*comm, coordinate, weight, tolerance);
  }
  return moved;
}

void RankGrid::place_rank() {
  const RankCounts n = counts();
  if (n[0] * n[1] * n[2] != comm->size())
    throw std::runtime_error(std::to_string(n[0]) + " x " + std::to_string(n[1]) + " x " + std::to_string(n[2]) +
                             " sub-domains for " + std::to_string(comm->size()) + " ranks");
  int r = comm->rank();
  axes[2].index = r % n[2];
  r /= n[2];
  axes[1].index = r % n[1];
  axes[0].index = r / n[1];
  if (!axes[slab_axis].split())  // the pair list's half shell must point across a cut, if any
    for (int a = 0; a < 3; ++a)
      if (axes[a].slabs() > axes[slab_axis].slabs()) slab_axis = a;
}

RankGrid RankGrid::balanced(const Communicator& comm, const Domain& domain, const RankCounts& counts,
                            const std::vector<Vec3>& positions, double min_width, int slab_axis) {
  RankGrid g;
  g.comm = &comm;
  g.slab_axis = slab_axis;
  std::vector<double> coordinate(positions.size());
  for (int a = 0; a < 3; ++a) {
    for (std::size_t i = 0; i < positions.size(); ++i) coordinate[i] = positions[i][a];
    g.axes[a] = counts[a] > 1 ? SlabDecomposition::balanced(domain, a, counts[a], coordinate, min_width)
                              : SlabDecomposition::whole(domain, a);
  }
  g.place_rank();
  return g;
}

RankGrid RankGrid::slabs(const Communicator& comm, const Domain& domain, int axis, std::vector<double> cut,
                         double min_width) {
  std::array<std::vector<double>, 3> cuts;
  cuts[axis] = std::move(cut);
  return with_cuts(comm, domain, std::move(cuts), min_width, axis);
}

RankGrid RankGrid::with_cuts(const Communicator& comm, const Domain& domain, std::array<std::vector<double>, 3> cut,
                             double min_width, int slab_axis) {
  RankGrid g;
  g.comm = &comm;
  g.slab_axis = slab_axis;
  for (int a = 0; a < 3; ++a)
    g.axes[a] = cut[a].size() > 2 ? SlabDecomposition::with_cuts(domain, a, std::move(cut[a]), min_width)
                                  : SlabDecomposition::whole(domain, a);
  for (int a = 0; a < 3; ++a) g.axes[a].min_width = min_width;
  g.place_rank();
  return g;
}

RankCounts RankGrid::choose_counts(int ranks, const Vec3& extent, const std::array<bool, 3>& periodic, double range,
                                   int preferred) {
  RankCounts slabs{1, 1, 1};
  slabs[preferred] = ranks;
  if (ranks == 1 || extent[preferred] / ranks >= 4 * range) return slabs;
  RankCounts best = slabs;
  double best_area = std::numeric_limits<double>::infinity();
  for (int px = 1; px <= ranks; ++px) {
    if (ranks % px) continue;
    for (int py = 1; py <= ranks / px; ++py) {
      if ((ranks / px) % py) continue;
      const RankCounts n{px, py, ranks / px / py};
      double area = 0;
      bool feasible = true;
      for (int a = 0; a < 3; ++a) {
        if (n[a] == 1) continue;
        feasible &= extent[a] / n[a] >= range;
        const int planes = periodic[a] ? n[a] : n[a] - 1;  // cut planes across the box
        area += planes * extent[(a + 1) % 3] * extent[(a + 2) % 3];
      }
      if (feasible && area < best_area * (1 - 1e-12)) best = n, best_area = area;
    }
  }
  return best;
}

}  // namespace talus
