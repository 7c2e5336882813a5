#include "talus/world/sphere_elastic_batch.h"

#include <algorithm>
#include <cmath>

namespace talus {

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
    const double fn = kn[k] * overlap - eta_n[k] * vn;  // Eq. (3)
    const double f_max = mu[k] * std::abs(fn);
    Vec3 s{sx[k], sy[k], sz[k]};
    s += (vt - (dot(s, vij) * inv_dist) * n) * dt;      // Eq. (9), forward Euler
    Vec3 ft = -kt[k] * s - eta_t[k] * vt;               // Eq. (7)
    const double ft2 = norm2(ft);
    // Alg. 2: truncate to mu |f_n|. Both branches are computed and one is selected (a vector
    // runs them all); the unused one may divide by zero harmlessly.
    const bool slides = ft2 > f_max * f_max;
    const double truncation = f_max / std::sqrt(ft2);
    ft *= slides ? truncation : 1.0;
    const double inv_kt = -1.0 / kt[k];
    const double back = kt[k] > 0 ? inv_kt : 0.0;
    const Vec3 s_slid = (ft + eta_t[k] * vt) * back;
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

}  // namespace talus
