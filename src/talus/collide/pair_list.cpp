#include "talus/collide/pair_list.h"

#include <omp.h>

#include <algorithm>

#include "talus/world/parallel.h"

namespace talus {

void ContactMemory::resize(std::size_t n, const MemoryLayout& layout) {
  spring.assign(layout.spring ? n : 0, Vec3{});
  normal_prev.assign(layout.normal_prev ? n : 0, Vec3{});
  rolling.assign(layout.rolling ? n : 0, Vec3{});
}

bool ContactMemory::active(std::size_t e) const {
  if (!normal_prev.empty()) return norm2(normal_prev[e]) > 0;
  if (!spring.empty()) return norm2(spring[e]) > 0;
  return !rolling.empty() && norm2(rolling[e]) > 0;
}

void ContactMemory::clear(std::size_t e) {
  if (!spring.empty()) spring[e] = {};
  if (!normal_prev.empty()) normal_prev[e] = {};
  if (!rolling.empty()) rolling[e] = {};
}

void ContactMemory::copy_from(const ContactMemory& src, std::size_t from, std::size_t to, bool reversed) {
  // Seen from the other body every memory changes sign: delta_t, the normal and M_k.
  const double s = reversed ? -1.0 : 1.0;
  if (!spring.empty() && !src.spring.empty()) spring[to] = s * src.spring[from];
  if (!normal_prev.empty() && !src.normal_prev.empty()) normal_prev[to] = s * src.normal_prev[from];
  if (!rolling.empty() && !src.rolling.empty()) rolling[to] = s * src.rolling[from];
}

void PairList::build(const ParticleStore& p, const std::vector<CellCoord>& cell_of, const CellGrid& grid,
                     double skin, const MemoryLayout& layout) {
  const std::size_t owned = p.owned;
  const int s_axis = grid.slab_axis();
  row_.assign(owned + 1, 0);

  // Slab ranges: owned particles arrive sorted by slab.
  const int slab_count = grid.cells(s_axis);
  slab_start_.assign(slab_count + 1, 0);
  for (std::size_t i = 0; i < owned; ++i) ++slab_start_[cell_of[i][s_axis] + 1];
  for (int s = 0; s < slab_count; ++s) slab_start_[s + 1] += slab_start_[s];

  // Each thread lists a contiguous block of rows; blocks are joined in order, so the list
  // is the same for any thread count.
  const int threads = worth_parallel(owned) ? omp_get_max_threads() : 1;
  std::vector<std::vector<std::uint32_t>> block_neighbors(threads);
#pragma omp parallel num_threads(threads)
  {
    const int t = omp_get_thread_num();
    const int nt = omp_get_num_threads();
    const std::size_t lo = owned * t / nt, hi = owned * (t + 1) / nt;
    auto& out = block_neighbors[t];
    out.clear();
    for (std::size_t i = lo; i < hi; ++i) {
      const CellCoord ci = cell_of[i];
      const Vec3 xi = p.position[i];
      const double ri = p.radius[i] + skin;
      const bool fixed_i = p.inv_mass[i] == 0.0;
      const std::uint32_t gi = p.gid[i];
      const int si = ci[s_axis];
      CellCoord c;
      for (c[0] = std::max(ci[0] - 1, grid.first(0)); c[0] <= std::min(ci[0] + 1, grid.last(0)); ++c[0])
        for (c[1] = std::max(ci[1] - 1, grid.first(1)); c[1] <= std::min(ci[1] + 1, grid.last(1)); ++c[1])
          for (c[2] = std::max(ci[2] - 1, grid.first(2)); c[2] <= std::min(ci[2] + 1, grid.last(2)); ++c[2]) {
            const int sc = c[s_axis];
            if (sc < si) continue;
            const std::int64_t cell = grid.linear(c);
            for (const std::uint32_t* it = grid.begin(cell); it != grid.end(cell); ++it) {
              const std::uint32_t j = *it;
              if (j == i) continue;
              if (sc == si && !(gi < p.gid[j])) continue;  // same slab: the lower global id lists the pair
              if (fixed_i && p.inv_mass[j] == 0.0) continue;
              const double range = ri + p.radius[j];
              if (norm2(p.position[j] - xi) < range * range) out.push_back(j);
            }
          }
      row_[i + 1] = static_cast<std::uint32_t>(out.size());
    }
  }
  // Turn per-block counts into global row offsets.
  std::size_t offset = 0;
  neighbor_.clear();
  for (int t = 0; t < threads; ++t) {
    const std::size_t lo = owned * t / threads, hi = owned * (t + 1) / threads;
    for (std::size_t i = lo; i < hi; ++i) row_[i + 1] += static_cast<std::uint32_t>(offset);
    offset += block_neighbors[t].size();
    neighbor_.insert(neighbor_.end(), block_neighbors[t].begin(), block_neighbors[t].end());
  }
  memory.resize(neighbor_.size(), layout);
}

std::vector<std::int32_t> rows_by_global_id(std::size_t rows, const std::vector<std::uint32_t>& gid,
                                            std::size_t gid_limit) {
  std::vector<std::int32_t> row_of(gid_limit, -1);
  for (std::size_t i = 0; i < rows; ++i) row_of[gid[i]] = static_cast<std::int32_t>(i);
  return row_of;
}

void PairList::transfer_memory(const PairList& old, const std::vector<std::uint32_t>& old_gid,
                               const std::vector<std::uint32_t>& gid, std::size_t gid_limit,
                               std::vector<std::int64_t>* origin) {
  if (origin) origin->assign(entries(), 0);
  if (old.entries() == 0) return;
  const std::vector<std::int32_t> old_row_of = rows_by_global_id(old.rows(), old_gid, gid_limit);
  auto find = [&](std::uint32_t a, std::uint32_t b) -> std::int64_t {
    const std::int32_t r = old_row_of[a];
    if (r < 0) return -1;
    for (std::uint32_t e = old.row_begin(r); e < old.row_end(r); ++e)
      if (old_gid[old.neighbor(e)] == b) return e;
    return -1;
  };
#pragma omp parallel for schedule(static) if (worth_parallel(rows()))
  for (std::size_t i = 0; i < rows(); ++i) {
    for (std::uint32_t e = row_[i]; e < row_[i + 1]; ++e) {
      const std::uint32_t a = gid[i], b = gid[neighbor_[e]];
      std::int64_t f = find(a, b);
      bool reversed = false;
      if (f < 0) {
        f = find(b, a);
        reversed = true;
      }
      if (f >= 0 && old.memory.active(f)) memory.copy_from(old.memory, f, e, reversed);
      if (f >= 0 && origin) (*origin)[e] = reversed ? -(f + 1) : f + 1;
    }
  }
}

std::size_t PairList::bytes() const {
  return row_.capacity() * 4 + neighbor_.capacity() * 4 + slab_start_.capacity() * 4 +
         (memory.spring.capacity() + memory.normal_prev.capacity() + memory.rolling.capacity()) * sizeof(Vec3);
}

}  // namespace talus
