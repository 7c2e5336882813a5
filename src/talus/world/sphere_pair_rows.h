#pragma once
// The sphere pair loop over a range of neighbour-list rows, in two passes over batches of
// entries: a distance test that gathers the touching entries, then the contact law on those
// only. Touching and apart entries alternate at random (one in four or five touches in the
// chute); split, the first pass is a short loop with one rare branch, and the second runs the same
// path for every contact, which lets the elastic-spring law run four contacts per vector
// instruction (sphere_elastic_batch.h).
#include <cstdint>

#if defined(__AVX512F__) && defined(__AVX512VL__) && defined(__AVX512BW__)
#include <immintrin.h>
#define TALUS_PAIR_ROWS_AVX512 1
#else
#define TALUS_PAIR_ROWS_AVX512 0
#endif

#include "talus/collide/pair_list.h"
#include "talus/contact/contact_table.h"
#include "talus/world/sphere_contact.h"
#include "talus/world/sphere_elastic_batch.h"

namespace talus {

// The particle and memory arrays the loop reads and writes (memories null when off).
struct SpherePairArrays {
  const Vec3* __restrict position;
  const Vec3* __restrict velocity;
  const Vec3* __restrict spin;
  const double* __restrict radius;
  const double* __restrict inv_mass;
  const std::int32_t* __restrict species;
  const std::uint32_t* __restrict neighbor;
  const std::uint32_t* __restrict row;  ///< CSR offsets: row i is [row[i], row[i + 1])
  Vec3* __restrict force;
  Vec3* __restrict torque;
  Vec3* __restrict spring;
  Vec3* __restrict normal_prev;
  Vec3* __restrict rolling;
  std::uint8_t* __restrict remembered;  ///< per entry: its memories may be non-zero (PairList::remembered)
  std::uint32_t owned;                  ///< owned particles (ghosts follow them)
  std::uint32_t reach;                  ///< PairList::forward_reach
};

// Forces of the pairs listed in rows [first, last), added to both particles of each pair in
// entry order (whatever the batches, so any split of the rows gives the same sums). The kept
// memories are compile-time flags, so the loops carry no null tests.
template <TangentialModel Model, bool kSpring, bool kNormal, bool kRolling, BatchLaw kBatch = BatchLaw::none>
[[gnu::noinline]] void sphere_pair_rows(const SpherePairArrays& a, const ContactTable& table, double memory_dt,
                                        std::uint32_t first, std::uint32_t last) {
  // The vector path covers the law of the periodic chute (Weinhart et al. 2012): elastic
  // spring, no rolling resistance, with linear or Hertz-Mindlin springs. Every other law runs
  // contact by contact.
  constexpr bool kVector = kBatch != BatchLaw::none;
  static_assert(!kVector || (Model == TangentialModel::elastic_spring && kSpring && !kNormal && !kRolling));
  constexpr std::uint32_t kSpringRowsAhead = 8;
  ContactBatch batch;

  std::uint32_t count = 0;  // a local, not batch.count: the stores into the batch cannot alias it
  const auto flush = [&](std::uint32_t& n) {
    batch.count = n;
    if constexpr (kVector) {
      sphere_elastic_batch<kBatch == BatchLaw::grown>(batch, a.position, a.velocity, a.spin, a.radius, a.inv_mass, a.species, table, a.spring, memory_dt);
      for (std::uint32_t k = 0; k < batch.count; ++k) {
        const std::uint32_t i = batch.i[k], j = batch.j[k];
        a.force[i] += batch.force_on_i(k);
        a.torque[i] += batch.torque_i(k);
        a.force[j] -= batch.force_on_i(k);
        a.torque[j] += batch.torque_j(k);
      }
    } else {
      for (std::uint32_t k = 0; k < batch.count; ++k) {
        const std::uint32_t e = batch.entry[k], i = batch.i[k], j = batch.j[k];
        const ContactMotion m{a.velocity[i], a.spin[i], a.velocity[j], a.spin[j]};
        const ContactHistoryRef h{kSpring ? a.spring + e : nullptr, kNormal ? a.normal_prev + e : nullptr,
                                  kRolling ? a.rolling + e : nullptr};
        const Vec3 d = a.position[i] - a.position[j];
        const ContactResult r = sphere_contact<Model>(d, norm2(d), a.radius[i], a.radius[j], m,
                                                      table.pair(a.species[i], a.species[j]),
                                                      1.0 / (a.inv_mass[i] + a.inv_mass[j]), memory_dt, h);
        a.force[i] += r.force_on_i;
        a.torque[i] += r.torque_i;
        a.force[j] -= r.force_on_i;
        a.torque[j] += r.torque_j;
      }
    }
    n = 0;
  };

  // Locals, not members of `a`: the byte stores below may alias any memory, so the compiler
  // would reload every base pointer from `a` at every entry.
  const Vec3* __restrict position = a.position;
  const double* __restrict radius = a.radius;
  const std::uint32_t* __restrict row = a.row;
  const std::uint32_t* __restrict neighbor = a.neighbor;
  std::uint8_t* __restrict remembered = a.remembered;
  // A contact has ended: a later one starts afresh.
  const auto forget = [&](std::uint32_t e) {
    if constexpr (kSpring) a.spring[e] = {};
    if constexpr (kNormal) a.normal_prev[e] = {};
    if constexpr (kRolling) a.rolling[e] = {};
  };
  for (std::uint32_t i = first; i < last; ++i) {
    // Row i is the first to meet particle i + reach, at a random place in the row: its data
    // would arrive as cache misses on the critical path. Asked for now, they are in cache by
    // then, and stay there until row i + reach, as the rows between touch only nearer data.
    // The springs of the rows a few ahead are asked for likewise (sparse reads, one in four
    // or five entries touches).
    if (const std::uint32_t ahead = i + a.reach; ahead < a.owned) {
      __builtin_prefetch(position + ahead);
      __builtin_prefetch(radius + ahead);
      __builtin_prefetch(a.velocity + ahead);
      __builtin_prefetch(a.spin + ahead);
      __builtin_prefetch(a.force + ahead, 1);
      __builtin_prefetch(a.torque + ahead, 1);
    }
    if constexpr (kSpring) {
      if (i + kSpringRowsAhead < last) {
        const std::uint32_t begin = row[i + kSpringRowsAhead], end = row[i + kSpringRowsAhead + 1];
        __builtin_prefetch(a.spring + begin, 1);
        __builtin_prefetch(a.spring + (end > begin ? end - 1 : begin), 1);
      }
    }
    const Vec3 xi = position[i];
    const double ri = radius[i];
    const std::uint32_t row_end = row[i + 1];
#if TALUS_PAIR_ROWS_AVX512
    // Eight entries per test: the row's neighbours are gathered, and the touching ones
    // compressed into the batch, in entry order as in the loop below (the squared distance
    // is summed with fused operations, so a pair touching to the last bit may differ).
    const __m512d xi_x = _mm512_set1_pd(xi.x), xi_y = _mm512_set1_pd(xi.y), xi_z = _mm512_set1_pd(xi.z);
    const __m512d ri8 = _mm512_set1_pd(ri);
    const __m256i i8 = _mm256_set1_epi32(static_cast<int>(i));
    const double* const coords = &position[0].x;
    for (std::uint32_t e = row[i]; e < row_end; e += 8) {
      if (count > ContactBatch::kSize - 8) flush(count);  // room for eight more
      const std::uint32_t left = row_end - e;
      const __mmask8 live = left >= 8 ? __mmask8(0xFF) : static_cast<__mmask8>((1u << left) - 1);
      const __m256i j8 = _mm256_maskz_loadu_epi32(live, neighbor + e);
      const __m256i j3 = _mm256_add_epi32(_mm256_slli_epi32(j8, 1), j8);  // a Vec3 is three doubles
      const __m512d zero = _mm512_setzero_pd();
      const __m512d dx = _mm512_sub_pd(xi_x, _mm512_mask_i32gather_pd(zero, live, j3, coords, 8));
      const __m512d dy = _mm512_sub_pd(xi_y, _mm512_mask_i32gather_pd(zero, live, j3, coords + 1, 8));
      const __m512d dz = _mm512_sub_pd(xi_z, _mm512_mask_i32gather_pd(zero, live, j3, coords + 2, 8));
      const __m512d reach = _mm512_add_pd(ri8, _mm512_mask_i32gather_pd(zero, live, j8, radius, 8));
      const __m512d dist2 = _mm512_fmadd_pd(dz, dz, _mm512_fmadd_pd(dy, dy, _mm512_mul_pd(dx, dx)));
      const __mmask8 touches = _mm512_mask_cmp_pd_mask(live, dist2, _mm512_mul_pd(reach, reach), _CMP_LT_OQ);
      const __m256i e8 = _mm256_add_epi32(_mm256_set1_epi32(static_cast<int>(e)), _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7));
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(batch.entry + count), _mm256_maskz_compress_epi32(touches, e8));
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(batch.j + count), _mm256_maskz_compress_epi32(touches, j8));
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(batch.i + count), i8);
      count += static_cast<std::uint32_t>(__builtin_popcount(touches));
      if constexpr (kSpring || kNormal) {
        const __m128i was = _mm_maskz_loadu_epi8(live, remembered + e);
        const auto ended = static_cast<__mmask8>(_mm_test_epi8_mask(was, was) & ~touches);
        _mm_mask_storeu_epi8(remembered + e, live, _mm_maskz_mov_epi8(touches, _mm_set1_epi8(1)));
        for (unsigned left_over = ended; left_over; left_over &= left_over - 1) [[unlikely]]
          forget(e + static_cast<std::uint32_t>(__builtin_ctz(left_over)));
      }
    }
#else
    for (std::uint32_t e = row[i]; e < row_end; ++e) {
      const std::uint32_t j = neighbor[e];
      const Vec3 d = xi - position[j];
      const double reach = ri + radius[j];
      const double dist2 = norm2(d);
      const bool touches = dist2 < reach * reach;
      batch.entry[count] = e;  // kept only if it touches
      batch.i[count] = i;
      batch.j[count] = j;
      count += touches;
      if constexpr (kSpring || kNormal) {
        // Apart: a later contact starts afresh. Rare (the contact just ended), so predicted.
        const bool ended = remembered[e] && !touches;
        remembered[e] = touches;
        if (ended) [[unlikely]] forget(e);
      }
      if (count == ContactBatch::kSize) flush(count);
    }
#endif
  }
  if (count) flush(count);
}

// The instance of sphere_pair_rows for the memories `memory` keeps and the law of `table`.
template <TangentialModel Model>
auto with_memory_flags(const ContactMemory& memory, const ContactTable& table) {
  using Rows = void (*)(const SpherePairArrays&, const ContactTable&, double, std::uint32_t, std::uint32_t);
  const bool spring = !memory.spring.empty(), normal = !memory.normal_prev.empty(), rolling = !memory.rolling.empty();
  if constexpr (Model == TangentialModel::elastic_spring) {
    if (spring && !normal && !rolling) {
      switch (batch_law(table)) {
        case BatchLaw::linear: return Rows{sphere_pair_rows<Model, true, false, false, BatchLaw::linear>};
        case BatchLaw::grown: return Rows{sphere_pair_rows<Model, true, false, false, BatchLaw::grown>};
        case BatchLaw::none: break;
      }
    }
  }
  if (rolling) return normal ? Rows{sphere_pair_rows<Model, true, true, true>} : Rows{sphere_pair_rows<Model, false, false, true>};
  if (normal) return spring ? Rows{sphere_pair_rows<Model, true, true, false>} : Rows{sphere_pair_rows<Model, false, true, false>};
  return spring ? Rows{sphere_pair_rows<Model, true, false, false>} : Rows{sphere_pair_rows<Model, false, false, false>};
}

}  // namespace talus
