#include "talus/collide/pair_list.h"

#include <omp.h>

#include <algorithm>
#include <cstring>

#if defined(__AVX512F__) && defined(__AVX512VL__) && defined(__AVX512BW__)
#include <immintrin.h>
#define TALUS_LIST_AVX512 1
#else
#define TALUS_LIST_AVX512 0
#endif

#include "talus/world/parallel.h"

namespace talus {

namespace {
// Makes room for n values in the memory `values` already holds: on this machine a page the
// system maps afresh costs about 1.4 us (fault and zeroing), and a rebuild of the
// 32,000-sphere chute would map some 1,500. An array that must grow frees its old memory
// first (the two never coexist) and takes 1/32 more, so that the next builds fit.
template <class T>
void make_room(std::vector<T>& values, std::size_t n) {
  if (n <= values.capacity()) return;
  std::vector<T>().swap(values);
  values.reserve(n + n / 32);
}

// Sizes `values` for n entries without writing those it already holds.
void size_for_overwrite(std::vector<Vec3>& values, std::size_t n) {
  make_room(values, n);
  values.resize(n);
}
}  // namespace

void ContactMemory::resize_for_overwrite(std::size_t n, const MemoryLayout& layout) {
  size_for_overwrite(spring, layout.spring ? n : 0);
  size_for_overwrite(normal_prev, layout.normal_prev ? n : 0);
  size_for_overwrite(rolling, layout.rolling ? n : 0);
}

void ContactMemory::resize(std::size_t n, const MemoryLayout& layout) {
  resize_for_overwrite(n, layout);
  // In parallel: the 32,000-sphere chute's list holds 6 MB of memories, a rebuild's largest
  // serial write when zeroed alone.
  const auto held = [](std::vector<Vec3>& values) { return values.empty() ? nullptr : values.data(); };
  Vec3* const arrays[3] = {held(spring), held(normal_prev), held(rolling)};
  const long entries = static_cast<long>(n);
#pragma omp parallel for schedule(static) if (worth_parallel(n))
  for (long e = 0; e < entries; ++e)
    for (Vec3* const values : arrays)
      if (values) values[e] = Vec3{};
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

namespace {

// Appends to `dst` from index n every candidate j in [it, end) that row i lists, and returns
// the new count. Whether j is listed is data: a branch on it would mispredict for about one
// candidate in three, so every candidate is written and the count advances only for listed
// ones (dst has room for the whole range). In i's own slab both rows see the pair and the
// lower global id lists it; fixed particles never pair with fixed ones.
// dst must have room for 8 more than the range (the vector form writes whole lanes).
template <bool kSameSlab, bool kFixedI>
std::size_t list_candidates(const ParticleStore& p, std::size_t i, const Vec3& xi, double ri, std::uint32_t gi,
                            const std::uint32_t* it, const std::uint32_t* end, std::uint32_t* dst, std::size_t n) {
  const double* __restrict radius = p.radius.data();
  const Vec3* __restrict position = p.position.data();
#if TALUS_LIST_AVX512
  // Eight candidates per test, gathered, the listed ones compressed into dst in order: a build
  // of the 32,000-sphere chute's list took 20-25 % less time on one thread. The squared
  // distance is summed with fused operations, so a pair at the edge of the skin to the last
  // bit may differ.
  const double* const coords = &position[0].x;
  const __m512d xi_x = _mm512_set1_pd(xi.x), xi_y = _mm512_set1_pd(xi.y), xi_z = _mm512_set1_pd(xi.z);
  const __m512d ri8 = _mm512_set1_pd(ri), zero = _mm512_setzero_pd();
  const __m256i i8 = _mm256_set1_epi32(static_cast<int>(i)), gi8 = _mm256_set1_epi32(static_cast<int>(gi));
  for (; it < end; it += 8) {
    const auto left = static_cast<std::size_t>(end - it);
    const __mmask8 live = left >= 8 ? __mmask8(0xFF) : static_cast<__mmask8>((1u << left) - 1);
    const __m256i j8 = _mm256_maskz_loadu_epi32(live, it);
    const __m256i j3 = _mm256_add_epi32(_mm256_slli_epi32(j8, 1), j8);  // a Vec3 is three doubles
    const __m512d dx = _mm512_sub_pd(_mm512_mask_i32gather_pd(zero, live, j3, coords, 8), xi_x);
    const __m512d dy = _mm512_sub_pd(_mm512_mask_i32gather_pd(zero, live, j3, coords + 1, 8), xi_y);
    const __m512d dz = _mm512_sub_pd(_mm512_mask_i32gather_pd(zero, live, j3, coords + 2, 8), xi_z);
    const __m512d range = _mm512_add_pd(ri8, _mm512_mask_i32gather_pd(zero, live, j8, radius, 8));
    const __m512d dist2 = _mm512_fmadd_pd(dz, dz, _mm512_fmadd_pd(dy, dy, _mm512_mul_pd(dx, dx)));
    __mmask8 listed = _mm512_mask_cmp_pd_mask(live, dist2, _mm512_mul_pd(range, range), _CMP_LT_OQ);
    if constexpr (kSameSlab) {
      const __m256i gj = _mm256_mmask_i32gather_epi32(_mm256_setzero_si256(), listed, j8, p.gid.data(), 4);
      listed &= _mm256_cmpneq_epi32_mask(j8, i8) & _mm256_cmpgt_epu32_mask(gj, gi8);
    }
    if constexpr (kFixedI) {
      const __m512d inv_mass = _mm512_mask_i32gather_pd(zero, listed, j8, p.inv_mass.data(), 8);
      listed &= _mm512_cmp_pd_mask(inv_mass, zero, _CMP_NEQ_UQ);
    }
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(dst + n), _mm256_maskz_compress_epi32(listed, j8));
    n += static_cast<std::size_t>(__builtin_popcount(listed));
  }
  return n;
#else
  for (; it != end; ++it) {
    const std::uint32_t j = *it;
    const double range = ri + radius[j];
    bool listed = norm2(position[j] - xi) < range * range;
    if constexpr (kSameSlab) listed &= (j != i) & (gi < p.gid[j]);
    if constexpr (kFixedI) listed &= p.inv_mass[j] != 0.0;
    dst[n] = j;
    n += listed;
  }
  return n;
#endif
}

}  // namespace

void PairList::build(const ParticleStore& p, const std::vector<CellCoord>& cell_of, const CellGrid& grid,
                     double skin, const MemoryLayout& layout) {
  const std::size_t owned = p.owned;
  const int s_axis = grid.slab_axis(), p_axis = (s_axis + 1) % 3, q_axis = (s_axis + 2) % 3;  // as CellGrid::linear
  const std::int64_t s_stride = grid.stride(s_axis), p_stride = grid.stride(p_axis);
  // The entries are listed into the memory the old ones held (they have been carried out of
  // the list), each block of rows into its own region. Particles keep nearly their order from
  // one build to the next (sorted by cell), so the old rows size the regions well; a block
  // that still outgrows its region goes on in a side array of its own.
  const auto old_entries = [&](std::size_t lo, std::size_t hi) -> double {  // row_ still holds the old rows
    const std::size_t rows = this->rows();
    return static_cast<double>(row_.empty() ? 0 : row_[std::min(hi, rows)] - row_[std::min(lo, rows)]);
  };
  clear();

  // Slab ranges: owned particles arrive sorted by slab.
  const int slab_count = grid.cells(s_axis);
  slab_start_.assign(slab_count + 1, 0);
  for (std::size_t i = 0; i < owned; ++i) ++slab_start_[cell_of[i][s_axis] + 1];
  for (int s = 0; s < slab_count; ++s) slab_start_[s + 1] += slab_start_[s];

  // Contiguous blocks of rows, listed by whichever thread is free and joined in order, so the
  // list is the same for any thread count. Rows differ in cost (a chute's dense base, its
  // dilute top): one block per thread left one thread waiting for a quarter of the listing.
  const int threads = worth_parallel(owned) ? omp_get_max_threads() : 1;
  const std::size_t blocks = threads > 1 ? std::min<std::size_t>(8 * threads, owned / 512 + 1) : 1;
  std::vector<std::size_t> region(blocks + 1, 0);  // block b's region: [region[b], region[b + 1])
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::size_t lo = owned * b / blocks, hi = owned * (b + 1) / blocks;
    region[b + 1] = region[b] + static_cast<std::size_t>(1.05 * old_entries(lo, hi)) + (hi - lo) / 8 + 16;
  }
  row_.assign(owned + 1, 0);
  make_room(neighbor_, region[blocks]);
  neighbor_.resize(region[blocks]);
  std::vector<std::vector<std::uint32_t>> overflow(blocks);
  std::vector<std::size_t> listed(blocks, 0);
  std::vector<std::uint32_t> block_reach(blocks, 0);
  const long block_count = static_cast<long>(blocks);
#pragma omp parallel num_threads(threads)
  {
    // One row's candidates, written past the listed count without branching, then cut.
    std::vector<std::uint32_t> row_candidates(256);
#pragma omp for schedule(dynamic, 1)
    for (long block = 0; block < block_count; ++block) {
      const auto b = static_cast<std::size_t>(block);
      const std::size_t lo = owned * b / blocks, hi = owned * (b + 1) / blocks;
      std::uint32_t* const in_region = neighbor_.data() + region[b];
      const std::size_t room = region[b + 1] - region[b];
      std::vector<std::uint32_t>& spill = overflow[b];
      std::uint32_t reach = 0;
      std::size_t n = 0;  // entries listed in this block
      for (std::size_t i = lo; i < hi; ++i) {
        const CellCoord ci = cell_of[i];
        const Vec3 xi = p.position[i];
        const double ri = p.radius[i] + skin;
        const bool fixed_i = p.inv_mass[i] == 0.0;
        const std::uint32_t gi = p.gid[i];
        const int si = ci[s_axis];
        std::size_t m = 0;  // this row's entries
        // The slab and the next one (pairs point up the slab axis), and in each the 3 x 3 cells
        // around i; cells along the fastest axis q are consecutive, so the three are one range
        // of items, from begin() of the first to end() of the last.
        const int p_lo = std::max(ci[p_axis] - 1, grid.first(p_axis)), p_hi = std::min(ci[p_axis] + 1, grid.last(p_axis));
        const int q_lo = std::max(ci[q_axis] - 1, grid.first(q_axis)), q_hi = std::min(ci[q_axis] + 1, grid.last(q_axis));
        CellCoord first = ci;
        first[p_axis] = p_lo;
        first[q_axis] = q_lo;
        const std::int64_t corner = grid.linear(first);
        const int slabs = std::min(si + 1, grid.last(s_axis)) - si + 1;
        for (int ds = 0; ds < slabs; ++ds) {
          for (int dp = 0; dp <= p_hi - p_lo; ++dp) {
            const std::int64_t run_first = corner + ds * s_stride + dp * p_stride;
            const std::uint32_t* const it = grid.begin(run_first);
            const std::uint32_t* const run_end = grid.end(run_first + (q_hi - q_lo));
            const std::size_t run = static_cast<std::size_t>(run_end - it);
            if (m + run + 8 > row_candidates.size()) row_candidates.resize(std::max(2 * row_candidates.size(), m + run + 8));
            std::uint32_t* const dst = row_candidates.data();
            if (ds == 0)
              m = fixed_i ? list_candidates<true, true>(p, i, xi, ri, gi, it, run_end, dst, m)
                          : list_candidates<true, false>(p, i, xi, ri, gi, it, run_end, dst, m);
            else
              m = fixed_i ? list_candidates<false, true>(p, i, xi, ri, gi, it, run_end, dst, m)
                          : list_candidates<false, false>(p, i, xi, ri, gi, it, run_end, dst, m);
          }
        }
        for (std::size_t e = 0; e < m; ++e) {
          const std::uint32_t j = row_candidates[e];
          if (j > i && j < owned) reach = std::max(reach, static_cast<std::uint32_t>(j - i));
          if (n + e < room)
            in_region[n + e] = j;
          else
            spill.push_back(j);
        }
        n += m;
        row_[i + 1] = static_cast<std::uint32_t>(n);
      }
      listed[b] = n;
      block_reach[b] = reach;
    }
  }
  forward_reach_ = *std::max_element(block_reach.begin(), block_reach.end());
  // Join the blocks in order: row offsets become global, and each block's entries move down to
  // follow the previous block's (never up past a region not yet moved, while no block spilled).
  std::size_t total = 0;
  bool spilled = false;
  for (std::size_t b = 0; b < blocks; ++b) {
    total += listed[b];
    spilled |= !overflow[b].empty();
  }
  std::vector<std::uint32_t> joined;
  if (spilled) joined.resize(total);  // seldom: the first build, or a list that grew by 5 %
  std::uint32_t* const out = spilled ? joined.data() : neighbor_.data();
  std::size_t offset = 0;
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::size_t lo = owned * b / blocks, hi = owned * (b + 1) / blocks;
    for (std::size_t i = lo; i < hi; ++i) row_[i + 1] += static_cast<std::uint32_t>(offset);
    const std::size_t kept = listed[b] - overflow[b].size();
    std::memmove(out + offset, neighbor_.data() + region[b], kept * sizeof(std::uint32_t));
    std::copy(overflow[b].begin(), overflow[b].end(), out + offset + kept);
    offset += listed[b];
  }
  if (spilled) {
    std::vector<std::uint32_t>().swap(neighbor_);
    neighbor_.reserve(total + total / 32);
    neighbor_.assign(joined.begin(), joined.end());
  } else {
    neighbor_.resize(total);
  }
  memory.resize(neighbor_.size(), layout);
  make_room(remembered_, neighbor_.size());
  remembered_.assign(neighbor_.size(), 0);
  split_slabs();
}

void PairList::clear() {
  neighbor_.clear();
  remembered_.clear();
  // The memories keep their length: the next build zeroes them in parallel, where growing
  // them back from empty would write every entry on one thread.
}

void PairList::remark_memories() {
  remembered_.resize(neighbor_.size());
  for (std::size_t e = 0; e < remembered_.size(); ++e) remembered_[e] = memory.active(e);
}

void PairList::split_slabs() {
  // Up to 32 chunks of about equal work, a slab or two each on the 32,000-sphere chute. The
  // pair pass ends when its last chunk does, so the chunk is the grain of the threads'
  // imbalance: with 16 chunks one of two threads waited 0.08-0.12 ms a step (7-10 % of the
  // pass), with 32 0.03-0.05 ms. Chunks follow the work, not the slabs.
  constexpr std::size_t kChunks = 32;
  const std::size_t slab_count = slabs();
  const std::size_t count = std::min(kChunks, slab_count);
  auto work = [&](std::size_t s) -> double { return static_cast<double>(row_[slab_start_[s]]) + slab_start_[s]; };
  const double total = slab_count ? work(slab_count) : 0.0;
  chunk_.assign(1, 0);
  for (std::size_t c = 1; c < count; ++c) {
    std::size_t s = chunk_.back() + 1;  // at least one slab per chunk
    while (s < slab_count - (count - c) && work(s) < total * static_cast<double>(c) / static_cast<double>(count)) ++s;
    chunk_.push_back(static_cast<std::uint32_t>(s));
  }
  chunk_.push_back(static_cast<std::uint32_t>(slab_count));
}

void PairList::carry(const std::vector<std::uint32_t>& gid, bool every_entry, CarriedContacts& c) const {
  // The byte flags kept by the sphere pair loop say the same as the memories (a zero flag
  // means a zero memory) in a twenty-fourth of the bytes. (Shaped bodies carry every entry.)
  const auto keep = [&](std::uint32_t e) { return every_entry || remembered_[e] != 0; };
  // One group per row, keyed by the row's global id (each row has one of its own), so rows
  // count and copy in parallel.
  const long rows_n = static_cast<long>(rows());
  const bool parallel = worth_parallel(rows());
  c.points.clear();  // the caller adds them, if it needs them
  c.key.assign(gid.begin(), gid.begin() + rows_n);
  c.start.assign(rows() + 1, 0);
#pragma omp parallel for schedule(static) if (parallel)
  for (long i = 0; i < rows_n; ++i) {
    std::uint32_t kept = 0;
    for (std::uint32_t e = row_[i]; e < row_[i + 1]; ++e) kept += keep(e);
    c.start[i + 1] = kept;
  }
  for (std::size_t i = 0; i < rows(); ++i) c.start[i + 1] += c.start[i];
  c.group_of.index_positions(c.key);
  const std::size_t kept = c.start[rows()];
  make_room(c.other, kept);
  c.other.resize(kept);
  if (every_entry) {  // the entries of origin (restore_memory), which only shaped bodies ask for
    make_room(c.entry, kept);
    c.entry.resize(kept);
  }
  MemoryLayout layout;
  layout.spring = !memory.spring.empty();
  layout.normal_prev = !memory.normal_prev.empty();
  layout.rolling = !memory.rolling.empty();
  c.memory.resize_for_overwrite(kept, layout);  // every record is written below
#pragma omp parallel for schedule(static) if (parallel)
  for (long i = 0; i < rows_n; ++i) {
    std::uint32_t k = c.start[i];
    for (std::uint32_t e = row_[i]; e < row_[i + 1]; ++e) {
      if (!keep(e)) continue;
      c.other[k] = gid[neighbor_[e]];
      if (every_entry) c.entry[k] = e;
      c.memory.copy_from(memory, e, k, false);
      ++k;
    }
  }
}

CarriedRecord carried_record(const CarriedContacts& c, std::uint32_t a, std::size_t k) {
  const auto at = [k](const std::vector<Vec3>& v) { return v.empty() ? Vec3{} : v[k]; };
  return {a, c.other[k], at(c.memory.spring), at(c.memory.normal_prev), at(c.memory.rolling)};
}

void group_records(const std::vector<CarriedRecord>& records, const MemoryLayout& layout, CarriedContacts& c,
                   std::vector<SubContactList>* points) {
  c.key.clear();
  c.group_of.reset(records.size() / 4);
  std::vector<std::uint32_t> group(records.size());
  for (std::size_t n = 0; n < records.size(); ++n) {
    std::int32_t g = c.group_of.find(records[n].a);
    if (g == GidIndex::kAbsent) {
      g = static_cast<std::int32_t>(c.key.size());
      c.group_of.put(records[n].a, g);
      c.key.push_back(records[n].a);
    }
    group[n] = static_cast<std::uint32_t>(g);
  }
  c.start.assign(c.groups() + 1, 0);
  for (const std::uint32_t g : group) ++c.start[g + 1];
  for (std::size_t g = 0; g < c.groups(); ++g) c.start[g + 1] += c.start[g];
  c.other.resize(records.size());
  c.entry.clear();
  c.points.clear();
  if (points) {
    c.entry.resize(records.size());
    c.points.resize(records.size());
  }
  c.memory.resize_for_overwrite(records.size(), layout);
  std::vector<std::uint32_t> fill(c.start.begin(), c.start.end() - 1);
  for (std::size_t n = 0; n < records.size(); ++n) {
    const CarriedRecord& r = records[n];
    const std::uint32_t k = fill[group[n]]++;
    c.other[k] = r.b;
    if (points) {
      c.entry[k] = k;
      c.points[k] = std::move((*points)[n]);
    }
    if (layout.spring) c.memory.spring[k] = r.spring;
    if (layout.normal_prev) c.memory.normal_prev[k] = r.normal_prev;
    if (layout.rolling) c.memory.rolling[k] = r.rolling;
  }
}

std::size_t CarriedContacts::bytes() const {
  return (key.capacity() + start.capacity() + other.capacity() + entry.capacity()) * 4 + group_of.bytes() +
         (memory.spring.capacity() + memory.normal_prev.capacity() + memory.rolling.capacity()) * sizeof(Vec3);
}

void PairList::restore_memory(const CarriedContacts& carried, const std::vector<std::uint32_t>& gid,
                              std::vector<std::int64_t>* origin) {
  if (origin) origin->assign(entries(), 0);
  if (carried.other.empty()) return;
  // Record by record, not entry by entry: only the entries that remembered a contact were
  // carried, fewer than half of the new ones. A record (a, b) is listed in the row of a, or
  // reversed in the row of b (a row lists each of its pairs once, and never one the other
  // row lists). Each record finds one entry and each entry at most one record, so the
  // records of different particles go to different threads without a race. Rows are taken
  // in order, so that the memories are written nearly in order; only a reversed pair (one
  // whose particles changed slab order) looks elsewhere.
  const long rows_n = static_cast<long>(rows());
  const bool parallel = worth_parallel(rows());
  // Alone: two threads writing at random into one table fight over its cache lines.
  row_of_gid_.index_positions(std::span<const std::uint32_t>(gid.data(), rows()));
  const auto find = [&](std::uint32_t a, std::uint32_t b) -> std::int64_t {  // entry of b in a's row, or -1
    const std::int32_t i = row_of_gid_.find(a);
    if (i < 0) return -1;
    for (std::uint32_t e = row_[i]; e < row_[i + 1]; ++e)
      if (gid[neighbor_[e]] == b) return e;
    return -1;
  };
#pragma omp parallel for schedule(static) if (parallel)
  for (long i = 0; i < rows_n; ++i) {
    const std::uint32_t a = gid[i];
    const std::int32_t g = carried.group_of.find(a);
    if (g < 0) continue;
    for (std::uint32_t k = carried.start[g]; k < carried.start[g + 1]; ++k) {
      const std::uint32_t b = carried.other[k];
      std::int64_t e = find(a, b);
      const bool reversed = e < 0;
      if (reversed) e = find(b, a);
      if (e < 0) continue;
      memory.copy_from(carried.memory, k, e, reversed);
      remembered_[e] = memory.active(e);
      if (origin) (*origin)[e] = reversed ? -(carried.entry[k] + std::int64_t{1}) : carried.entry[k] + std::int64_t{1};
    }
  }
}

void PairList::transfer_memory(const PairList& old, const std::vector<std::uint32_t>& old_gid,
                               const std::vector<std::uint32_t>& gid, std::vector<std::int64_t>* origin) {
  CarriedContacts carried;
  old.carry(old_gid, origin != nullptr, carried);
  restore_memory(carried, gid, origin);
}

std::size_t PairList::bytes() const {
  return row_.capacity() * 4 + neighbor_.capacity() * 4 + remembered_.capacity() + slab_start_.capacity() * 4 +
         row_of_gid_.bytes() +
         (memory.spring.capacity() + memory.normal_prev.capacity() + memory.rolling.capacity()) * sizeof(Vec3);
}

}  // namespace talus
