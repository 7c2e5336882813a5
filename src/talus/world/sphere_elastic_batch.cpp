#include "talus/world/sphere_elastic_batch.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "talus/contact/contact_law.h"

#if defined(__AVX512F__) && defined(__AVX512VL__)
#include <immintrin.h>
#define TALUS_BATCH_AVX512 1
#else
#define TALUS_BATCH_AVX512 0
#endif

namespace talus {

BatchLaw batch_law(const ContactTable& table) {
  const ContactParams& first = table.pair(0, 0);
  const bool linear = first.normal_law == normal_law_index<LinearNormal>();
  if (!linear && first.normal_law != normal_law_index<HertzNormal>()) return BatchLaw::none;
  for (int a = 0; a < table.species(); ++a)
    for (int b = 0; b < table.species(); ++b) {
      const ContactParams& p = table.pair(a, b);
      if (p.normal_law != first.normal_law || p.damping_scaling != first.damping_scaling ||
          p.tangential_law != first.tangential_law ||
          clamps_normal(p, TangentialModel::elastic_spring) != clamps_normal(first, TangentialModel::elastic_spring))
        return BatchLaw::none;
    }
  const bool grown = !linear || first.tangential_law != TangentialStiffness::constant;
  return grown ? BatchLaw::grown : BatchLaw::linear;
}

template <bool kGrown>
void sphere_elastic_batch(ContactBatch& b, const Vec3* __restrict position, const Vec3* __restrict velocity,
                          const Vec3* __restrict spin, const double* __restrict radius,
                          const double* __restrict inv_mass,
                          const std::int32_t* __restrict species, const ContactTable& table,
                          Vec3* __restrict spring, double dt) {
  constexpr std::uint32_t N = ContactBatch::kSize;
  const std::uint32_t n = b.count;
  // Whole vectors only: the padding lanes repeat the last contact and are never written back,
  // so every contact goes through the same instructions wherever it sits in a batch.
  const std::uint32_t lanes = std::min(N, (n + 7) & ~7u);
  alignas(64) double dx[N], dy[N], dz[N], dist2[N], ri[N], rj[N];
  alignas(64) double vx[N], vy[N], vz[N], wix[N], wiy[N], wiz[N], wjx[N], wjy[N], wjz[N];
  alignas(64) double sx[N], sy[N], sz[N], kn[N], eta_n[N], kt[N], eta_t[N], mu[N];
#if TALUS_BATCH_AVX512
  // Eight lanes per gather, stored whole; lanes past the count repeat the last contact, as in
  // the scalar loop below.
  const __m256i iota = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  const __m256i last = _mm256_set1_epi32(static_cast<int>(n - 1));
  const auto lane_indices = [&](const std::uint32_t* from, std::uint32_t k) {
    const __mmask8 live = _mm256_cmple_epu32_mask(_mm256_add_epi32(_mm256_set1_epi32(static_cast<int>(k)), iota), last);
    return _mm256_mask_loadu_epi32(_mm256_set1_epi32(static_cast<int>(from[n - 1])), live, from + k);
  };
  const auto triple = [](__m256i v) { return _mm256_add_epi32(_mm256_slli_epi32(v, 1), v); };  // a Vec3 is three doubles
  const auto gather = [](const double* base, __m256i index) {
    return _mm512_mask_i32gather_pd(_mm512_setzero_pd(), __mmask8(0xFF), index, base, 8);
  };
  const double* params = &table.pair(0, 0).normal_stiffness;
  constexpr int kParamDoubles = sizeof(ContactParams) / sizeof(double);
  static_assert(sizeof(ContactParams) % sizeof(double) == 0);
  const auto field = [&](std::size_t offset) { return params + offset / sizeof(double); };
  for (std::uint32_t k = 0; k < lanes; k += 8) {
    const __m256i i8 = lane_indices(b.i, k), j8 = lane_indices(b.j, k), e8 = lane_indices(b.entry, k);
    const __m256i i3 = triple(i8), j3 = triple(j8), e3 = triple(e8);
    const double* x = &position[0].x;
    const __m512d d_x = _mm512_sub_pd(gather(x, i3), gather(x, j3));
    const __m512d d_y = _mm512_sub_pd(gather(x + 1, i3), gather(x + 1, j3));
    const __m512d d_z = _mm512_sub_pd(gather(x + 2, i3), gather(x + 2, j3));
    _mm512_store_pd(dx + k, d_x);
    _mm512_store_pd(dy + k, d_y);
    _mm512_store_pd(dz + k, d_z);
    // The squares summed as the AVX-512 distance test sums them (sphere_pair_rows.h).
    _mm512_store_pd(dist2 + k, _mm512_fmadd_pd(d_z, d_z, _mm512_fmadd_pd(d_y, d_y, _mm512_mul_pd(d_x, d_x))));
    _mm512_store_pd(ri + k, gather(radius, i8));
    _mm512_store_pd(rj + k, gather(radius, j8));
    const double* v = &velocity[0].x;
    _mm512_store_pd(vx + k, _mm512_sub_pd(gather(v, i3), gather(v, j3)));
    _mm512_store_pd(vy + k, _mm512_sub_pd(gather(v + 1, i3), gather(v + 1, j3)));
    _mm512_store_pd(vz + k, _mm512_sub_pd(gather(v + 2, i3), gather(v + 2, j3)));
    const double* w = &spin[0].x;
    _mm512_store_pd(wix + k, gather(w, i3));
    _mm512_store_pd(wiy + k, gather(w + 1, i3));
    _mm512_store_pd(wiz + k, gather(w + 2, i3));
    _mm512_store_pd(wjx + k, gather(w, j3));
    _mm512_store_pd(wjy + k, gather(w + 1, j3));
    _mm512_store_pd(wjz + k, gather(w + 2, j3));
    const double* s = &spring[0].x;
    _mm512_store_pd(sx + k, gather(s, e3));
    _mm512_store_pd(sy + k, gather(s + 1, e3));
    _mm512_store_pd(sz + k, gather(s + 2, e3));
    const __m256i species_i = _mm256_i32gather_epi32(species, i8, 4), species_j = _mm256_i32gather_epi32(species, j8, 4);
    const __m256i pair = _mm256_mullo_epi32(
        _mm256_add_epi32(_mm256_mullo_epi32(species_i, _mm256_set1_epi32(table.species())), species_j),
        _mm256_set1_epi32(kParamDoubles));
    const __m512d reduced_mass = _mm512_div_pd(_mm512_set1_pd(1.0), _mm512_add_pd(gather(inv_mass, i8), gather(inv_mass, j8)));
    const __m512d sqrt_mass = _mm512_maskz_sqrt_pd(__mmask8(0xFF), reduced_mass);
    // DampingLaw::at, lane by lane to the bit: the square-root term only where it is set.
    const auto damping = [&](std::size_t law) {
      const __m512d eta = _mm512_fmadd_pd(gather(field(law + offsetof(DampingLaw, per_reduced_mass)), pair), reduced_mass,
                                          gather(field(law + offsetof(DampingLaw, coefficient)), pair));
      const __m512d per_sqrt = gather(field(law + offsetof(DampingLaw, per_sqrt_reduced_mass)), pair);
      const __mmask8 has_sqrt = _mm512_cmp_pd_mask(per_sqrt, _mm512_setzero_pd(), _CMP_NEQ_UQ);
      return _mm512_mask_blend_pd(has_sqrt, eta, _mm512_fmadd_pd(per_sqrt, sqrt_mass, eta));
    };
    _mm512_store_pd(kn + k, gather(field(offsetof(ContactParams, normal_stiffness)), pair));
    _mm512_store_pd(eta_n + k, damping(offsetof(ContactParams, normal_damping)));
    _mm512_store_pd(kt + k, gather(field(offsetof(ContactParams, tangential_stiffness)), pair));
    _mm512_store_pd(eta_t + k, damping(offsetof(ContactParams, tangential_damping)));
    _mm512_store_pd(mu + k, gather(field(offsetof(ContactParams, friction)), pair));
  }
#else
  for (std::uint32_t k = 0; k < lanes; ++k) {
    const std::uint32_t c = std::min(k, n - 1);
    const std::uint32_t i = b.i[c], j = b.j[c];
    const Vec3 d = position[i] - position[j];  // as the distance test had it, to the bit
    dx[k] = d.x;
    dy[k] = d.y;
    dz[k] = d.z;
    dist2[k] = norm2(d);
    ri[k] = radius[i];
    rj[k] = radius[j];
    const Vec3 vij = velocity[i] - velocity[j];
    vx[k] = vij.x;
    vy[k] = vij.y;
    vz[k] = vij.z;
    wix[k] = spin[i].x;
    wiy[k] = spin[i].y;
    wiz[k] = spin[i].z;
    wjx[k] = spin[j].x;
    wjy[k] = spin[j].y;
    wjz[k] = spin[j].z;
    const Vec3 s = spring[b.entry[c]];
    sx[k] = s.x;
    sy[k] = s.y;
    sz[k] = s.z;
    const ContactParams& p = table.pair(species[i], species[j]);
    const double reduced_mass = 1.0 / (inv_mass[i] + inv_mass[j]);
    kn[k] = p.normal_stiffness;
    eta_n[k] = p.normal_damping.at(reduced_mass);
    kt[k] = p.tangential_stiffness;
    eta_t[k] = p.tangential_damping.at(reduced_mass);
    mu[k] = p.friction;
  }
#endif
  // The law's options, the same for every pair (batch_law).
  const ContactParams& law = table.pair(0, 0);
  // As 0/1 weights, not bools: a loop-invariant bool select stops GCC from vectorising the loop.
  const double hertz = law.normal_law == normal_law_index<HertzNormal>() ? 1.0 : 0.0;
  const double tsuji = hertz > 0 && law.damping_scaling == DampingScaling::tsuji ? 1.0 : 0.0;
  const double mindlin = law.tangential_law == TangentialStiffness::mindlin ? 1.0 : 0.0;
  const double sliding_eta = coefficients_grow(law) ? 0.0 : 1.0;  // sliding_dashpot (contact_law.h)
  const double floor = clamps_normal(law, TangentialModel::elastic_spring) ? 0.0 : -std::numeric_limits<double>::infinity();
#pragma omp simd
  for (std::uint32_t k = 0; k < lanes; ++k) {
    // Geometry: Weinhart et al. 2012, branch vectors after Eq. (8).
    const double dist = std::sqrt(dist2[k]);
    const double inv_dist = 1.0 / dist;
    const Vec3 n{dx[k] * inv_dist, dy[k] * inv_dist, dz[k] * inv_dist};
    const double overlap = (ri[k] + rj[k]) - dist;
    const Vec3 arm_i = n * -(ri[k] - 0.5 * overlap);
    const Vec3 arm_j = n * (rj[k] - 0.5 * overlap);
    const Vec3 vij{vx[k], vy[k], vz[k]};
    const Vec3 vc = vij + cross(Vec3{wix[k], wiy[k], wiz[k]}, arm_i) - cross(Vec3{wjx[k], wjy[k], wjz[k]}, arm_j);
    const double vn = dot(vc, n);
    const Vec3 vt = vc - vn * n;
    double k_n = kn[k], e_n = eta_n[k], k_t = kt[k], e_t = eta_t[k];
    if constexpr (kGrown) {  // contact_coefficients, lane by lane: a = sqrt(R* delta)
      const double a = std::sqrt(ri[k] * rj[k] / (ri[k] + rj[k]) * overlap);
      const double damp = std::sqrt(a);
      const double normal_scale = 1.0 + hertz * (a - 1.0), damping_scale = 1.0 + tsuji * (damp - 1.0);
      k_n *= normal_scale;
      e_n *= damping_scale;
      e_t *= damping_scale;
      k_t *= 1.0 + mindlin * (a - 1.0);
    }
    const double fn_free = k_n * overlap - e_n * vn;
    const double fn = fn_free > floor ? fn_free : floor;  // Eq. (3); Huet et al. 2021, Eq. (5) when clamped
    const double f_max = mu[k] * std::abs(fn);
    Vec3 s{sx[k], sy[k], sz[k]};
    s += (vt - (dot(s, vij) * inv_dist) * n) * dt;      // Eq. (9), forward Euler
    Vec3 ft = -k_t * s - e_t * vt;                      // Eq. (7)
    const double ft2 = norm2(ft);
    // Alg. 2: truncate to mu |f_n|. Both branches are computed and one is selected (a vector
    // runs them all); the unused one may divide by zero harmlessly.
    const bool slides = ft2 > f_max * f_max;
    const double truncation = f_max / std::sqrt(ft2);
    ft *= slides ? truncation : 1.0;
    const double inv_kt = -1.0 / k_t;
    const double back = k_t > 0 ? inv_kt : 0.0;
    const Vec3 s_slid = (ft + (sliding_eta * e_t) * vt) * back;
    sx[k] = slides ? s_slid.x : s.x;
    sy[k] = slides ? s_slid.y : s.y;
    sz[k] = slides ? s_slid.z : s.z;
    const Vec3 f = fn * n + ft;
    const Vec3 ti = cross(arm_i, f);
    const Vec3 tj = cross(arm_j, -f);
    b.fx[k] = f.x;
    b.fy[k] = f.y;
    b.fz[k] = f.z;
    b.tix[k] = ti.x;
    b.tiy[k] = ti.y;
    b.tiz[k] = ti.z;
    b.tjx[k] = tj.x;
    b.tjy[k] = tj.y;
    b.tjz[k] = tj.z;
  }
  for (std::uint32_t k = 0; k < n; ++k) spring[b.entry[k]] = {sx[k], sy[k], sz[k]};
}

template void sphere_elastic_batch<false>(ContactBatch&, const Vec3*, const Vec3*, const Vec3*, const double*,
                                          const double*, const std::int32_t*, const ContactTable&, Vec3*, double);
template void sphere_elastic_batch<true>(ContactBatch&, const Vec3*, const Vec3*, const Vec3*, const double*,
                                         const double*, const std::int32_t*, const ContactTable&, Vec3*, double);

}  // namespace talus
