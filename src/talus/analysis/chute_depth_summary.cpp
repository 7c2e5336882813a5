#include "talus/analysis/chute_depth_summary.h"

#include <algorithm>
#include <cmath>

#include "talus/analysis/cg_balance.h"

namespace talus {

std::optional<double> bulk_density(const std::vector<double>& z, const std::vector<double>& rho, const FlowSurface& fs,
                                   double diameter) {
  const double lo = fs.base + 2 * diameter, hi = fs.surface - 4 * diameter;
  if (hi <= lo) return std::nullopt;
  return integrate_profile(z, rho, lo, hi) / (hi - lo);  // Weinhart et al. 2012, Eq. (51)
}

ChuteDepthSummary summarize_chute_profile(const CgFields& profile, const Vec3& gravity, double particle_density,
                                          double diameter, double mass_per_area, double kappa) {
  ChuteDepthSummary r;
  r.averages = depth_averages(profile, kappa);
  const FlowSurface& fs = r.averages.surface;
  const double h = fs.height(), g = norm(gravity), g_normal = -gravity.z;
  r.angle = std::atan2(gravity.x, g_normal);
  r.froude = r.averages.velocity / std::sqrt(g_normal * h);  // Weinhart et al. 2012, Eq. (36)
  r.volume_fraction = r.averages.density / particle_density;

  const std::vector<double> z = profile_z(profile);
  const std::size_t n = z.size();
  std::vector<double> rho(n), weight(n);
  for (std::size_t k = 0; k < n; ++k) {
    rho[k] = profile.values[k].density;
    weight[k] = rho[k] * g_normal;
  }
  if (auto bulk = bulk_density(z, rho, fs, diameter)) r.bulk_volume_fraction = *bulk / particle_density;

  const std::vector<double> szz = profile_stress_on_planes(profile, 2), sxz = profile_stress_on_planes(profile, 0);
  // sigma_zz at the base: interpolate the profile at b.
  const auto at = [&](const std::vector<double>& q, double x) {
    if (x <= z.front()) return q.front();
    for (std::size_t k = 0; k + 1 < n; ++k)
      if (x <= z[k + 1]) return q[k] + (q[k + 1] - q[k]) * (x - z[k]) / (z[k + 1] - z[k]);
    return q.back();
  };
  const double szz_base = at(szz, fs.base);
  r.mu_base = szz_base != 0 ? -at(sxz, fs.base) / szz_base : 0;
  // The base carries the whole weight: the base-extended sigma_zz below the flow (its maximum).
  if (mass_per_area > 0) r.weight_error = *std::max_element(szz.begin(), szz.end()) / (mass_per_area * g_normal) - 1;

  const BalanceResiduals res = steady_balance(profile, gravity);
  double mom2 = 0, mass2 = 0, lay2 = 0, span = 0, bulk_span = 0;
  const double rho_bar = r.averages.density;
  const double rho_bulk = r.bulk_volume_fraction ? *r.bulk_volume_fraction * particle_density : rho_bar;
  const double dz = n > 1 ? z[1] - z[0] : 0;
  for (std::size_t k = 0; k < n; ++k) {
    if (z[k] < fs.base || z[k] > fs.surface) continue;
    // Weinhart et al. 2012, Eq. (41): sigma_zz(z) = ∫_z^inf rho g cos(theta) dz'.
    const double litho = integrate_profile(z, weight, z[k], z.back());
    r.lithostatic_error = std::max(r.lithostatic_error, std::abs(szz[k] - litho) / szz_base);
    if (z[k] <= fs.surface - 4 * diameter && szz[k] > 0)
      r.max_angle_deviation = std::max(r.max_angle_deviation, std::abs(std::atan(-sxz[k] / szz[k]) - r.angle));
    mom2 += (res.momentum[k].x * res.momentum[k].x + res.momentum[k].y * res.momentum[k].y +
             res.momentum[k].z * res.momentum[k].z) * dz;
    mass2 += res.mass[k] * res.mass[k] * dz;
    span += dz;
    if (z[k] >= fs.base + 2 * diameter && z[k] <= fs.surface - 4 * diameter) {
      lay2 += (rho[k] / rho_bulk - 1) * (rho[k] / rho_bulk - 1) * dz;
      bulk_span += dz;
    }
  }
  if (span > 0 && rho_bar > 0) {
    r.momentum_residual = std::sqrt(mom2 / span) / (rho_bar * g);
    r.mass_residual = std::sqrt(mass2 / span) / (rho_bar * std::sqrt(g / diameter));
  }
  if (bulk_span > 0) r.layering = std::sqrt(lay2 / bulk_span);
  return r;
}

}  // namespace talus
