#include "talus/collide/cell_grid.h"

#include <algorithm>
#include <cmath>

namespace talus {

void CellGrid::setup(const Domain& domain, const std::vector<Vec3>& position, std::size_t owned,
                     double range, int slab_axis) {
  Vec3 lo = domain.lo, hi = domain.hi;
  if (owned > 0) {
    Vec3 mn = position[0], mx = position[0];
    for (std::size_t i = 1; i < owned; ++i)
      for (int a = 0; a < 3; ++a) {
        mn[a] = std::min(mn[a], position[i][a]);
        mx[a] = std::max(mx[a], position[i][a]);
      }
    for (int a = 0; a < 3; ++a)
      if (!domain.periodic[a]) lo[a] = mn[a], hi[a] = mx[a];
  }
  for (int a = 0; a < 3; ++a)
    count_[a] = std::max(1, static_cast<int>(std::min(std::floor((hi[a] - lo[a]) / range), 1e6)));
  // A stray particle far away must not make the grid huge: cap the cells at a few per particle.
  const double limit = std::max<double>(4096, 4.0 * static_cast<double>(owned));
  while (static_cast<double>(count_[0] + 2) * (count_[1] + 2) * (count_[2] + 2) > limit) {
    int a = 0;
    for (int b = 1; b < 3; ++b)
      if (count_[b] > count_[a]) a = b;
    if (count_[a] == 1) break;
    count_[a] = (count_[a] + 1) / 2;
  }
  for (int a = 0; a < 3; ++a) {
    const double extent = hi[a] - lo[a];
    const int n = count_[a];
    origin_[a] = lo[a];
    width_[a] = extent > 0 ? extent / n : range;
    first_[a] = domain.periodic[a] ? -1 : 0;
    last_[a] = domain.periodic[a] ? n : n - 1;
  }
  slab_axis_ = slab_axis >= 0 ? slab_axis : most_even_axis(position, owned);
  const int s = slab_axis_, p = (s + 1) % 3, q = (s + 2) % 3;
  stride_[q] = 1;
  stride_[p] = last_[q] - first_[q] + 1;
  stride_[s] = stride_[p] * (last_[p] - first_[p] + 1);
}

int CellGrid::most_even_axis(const std::vector<Vec3>& position, std::size_t owned) const {
  // Slabs are the units the pair pass shares between threads, so they should hold equal
  // shares of the particles: the axis whose cell layers have the largest participation ratio
  // (sum n)^2 / sum n^2, the number of equally filled layers that would give the same spread.
  // A chute's depth has the most cells (a few grains saltate far above the flow) but only
  // half as many filled layers as its length.
  // A sample of about 4,096 particles estimates it well at a tenth of the cost of all (this
  // runs alone at every rebuild).
  const std::size_t stride = std::max<std::size_t>(1, owned / 4096);
  std::array<std::vector<std::uint32_t>, 3> layer;
  for (int a = 0; a < 3; ++a) layer[a].assign(count_[a], 0);
  double sampled = 0;
  for (std::size_t i = 0; i < owned; i += stride, ++sampled) {
    const CellCoord c = coord_of(position[i]);
    for (int a = 0; a < 3; ++a) ++layer[a][c[a]];
  }
  int best = 0;
  double best_spread = -1;
  for (int a = 0; a < 3; ++a) {
    double sum_sq = 0;
    for (const std::uint32_t n : layer[a]) sum_sq += static_cast<double>(n) * n;
    const double spread = sum_sq > 0 ? sampled * sampled / sum_sq : count_[a];
    if (spread > best_spread * (1 + 1e-9)) best = a, best_spread = spread;
  }
  return best;
}

CellCoord CellGrid::coord_of(const Vec3& x) const {
  CellCoord c;
  for (int a = 0; a < 3; ++a) {
    const int k = static_cast<int>(std::floor((x[a] - origin_[a]) / width_[a]));
    c[a] = std::clamp(k, 0, count_[a] - 1);
  }
  return c;
}

std::int64_t CellGrid::linear_size() const {
  std::int64_t n = 1;
  for (int a = 0; a < 3; ++a) n *= last_[a] - first_[a] + 1;
  return n;
}

void CellGrid::bin(const std::vector<CellCoord>& cell_of) {
  start_.assign(linear_size() + 1, 0);
  for (const auto& c : cell_of) ++start_[linear(c) + 1];
  for (std::size_t k = 1; k < start_.size(); ++k) start_[k] += start_[k - 1];
  items_.resize(cell_of.size());
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t i = 0; i < cell_of.size(); ++i) items_[fill[linear(cell_of[i])]++] = static_cast<std::uint32_t>(i);
}

}  // namespace talus
