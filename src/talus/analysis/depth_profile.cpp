#include "talus/analysis/depth_profile.h"

#include <algorithm>
#include <stdexcept>

namespace talus {
namespace {

void check_profile(const std::vector<double>& z, const std::vector<double>& q) {
  if (z.size() < 2 || z.size() != q.size()) throw std::invalid_argument("depth profile: need >= 2 matching points");
}

// z where q crosses level between points k and k+1.
double crossing(const std::vector<double>& z, const std::vector<double>& q, std::size_t k, double level) {
  const double dq = q[k + 1] - q[k];
  const double t = dq != 0 ? (level - q[k]) / dq : 0;
  return z[k] + std::clamp(t, 0.0, 1.0) * (z[k + 1] - z[k]);
}

}  // namespace

FlowSurface flow_surface(const std::vector<double>& z, const std::vector<double>& sigma_zz, double kappa) {
  check_profile(z, sigma_zz);
  const std::size_t n = z.size();
  const std::size_t kmax = std::max_element(sigma_zz.begin(), sigma_zz.end()) - sigma_zz.begin();
  const double top = sigma_zz[kmax];
  if (!(top > 0)) throw std::invalid_argument("flow_surface: sigma_zz has no positive maximum");
  // Eq. 42a, above the maximum.
  double z1 = z[n - 1];
  for (std::size_t k = kmax; k + 1 < n; ++k)
    if (sigma_zz[k + 1] < (1 - kappa) * top) {
      z1 = crossing(z, sigma_zz, k, (1 - kappa) * top);
      break;
    }
  // Eq. 42b: the last point above kappa max.
  double z2 = z[kmax];
  for (std::size_t k = n; k-- > 0;)
    if (sigma_zz[k] > kappa * top) {
      z2 = k + 1 < n ? crossing(z, sigma_zz, k, kappa * top) : z[k];
      break;
    }
  // Eq. 42c.
  const double ext = kappa / (1 - 2 * kappa) * (z2 - z1);
  return {z1 - ext, z2 + ext};
}

double integrate_profile(const std::vector<double>& z, const std::vector<double>& q, double from, double to) {
  check_profile(z, q);
  if (to < from) return -integrate_profile(z, q, to, from);
  const std::size_t n = z.size();
  double sum = 0;
  // Constant extension below z[0] and above z[n-1].
  if (from < z[0]) sum += q[0] * (std::min(to, z[0]) - from);
  if (to > z[n - 1]) sum += q[n - 1] * (to - std::max(from, z[n - 1]));
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const double a = std::max(from, z[k]), b = std::min(to, z[k + 1]);
    if (b <= a) continue;
    const double span = z[k + 1] - z[k];
    const auto at = [&](double x) { return q[k] + (q[k + 1] - q[k]) * (x - z[k]) / span; };
    sum += 0.5 * (at(a) + at(b)) * (b - a);
  }
  return sum;
}

double depth_average(const std::vector<double>& z, const std::vector<double>& q, const FlowSurface& fs) {
  if (!(fs.height() > 0)) throw std::invalid_argument("depth_average: empty flow");
  return integrate_profile(z, q, fs.base, fs.surface) / fs.height();
}

std::vector<double> profile_z(const CgFields& profile) {
  const CgGrid& g = profile.grid;
  if (g.dim() != 1 || !g.resolved[2]) throw std::invalid_argument("depth profile: need a 1D grid along z");
  std::vector<double> z(g.n[2]);
  for (int k = 0; k < g.n[2]; ++k) z[k] = g.coordinate(2, k);
  return z;
}

std::vector<double> profile_stress(const CgFields& profile, int row, int col) {
  std::vector<double> s(profile.values.size());
  for (std::size_t k = 0; k < s.size(); ++k) s[k] = profile.values[k].stress()(row, col);
  return s;
}

std::vector<double> profile_stress_on_planes(const CgFields& profile, int row) {
  const std::vector<double> z = profile_z(profile);
  std::vector<double> s = profile_stress(profile, row, 2);
  double above = 0;  // ∫_z^top t_b dz, trapezoid from the top down
  for (std::size_t k = s.size(); k-- > 0;) {
    if (k + 1 < s.size())
      above += 0.5 * (profile.values[k].boundary_force[row] + profile.values[k + 1].boundary_force[row]) * (z[k + 1] - z[k]);
    s[k] += above;
  }
  return s;
}

DepthAverages depth_averages(const CgFields& profile, double kappa) {
  const std::vector<double> z = profile_z(profile);
  const std::size_t n = z.size();
  std::vector<double> rho(n), u(n), u2(n);
  for (std::size_t k = 0; k < n; ++k) {
    rho[k] = profile.values[k].density;
    u[k] = profile.values[k].velocity().x;
    u2[k] = u[k] * u[k];
  }
  const std::vector<double> szz = profile_stress_on_planes(profile, 2);
  DepthAverages d;
  d.surface = flow_surface(z, szz, kappa);
  d.density = depth_average(z, rho, d.surface);
  d.velocity = depth_average(z, u, d.surface);
  d.shape_factor = d.velocity != 0 ? depth_average(z, u2, d.surface) / (d.velocity * d.velocity) : 0;
  const double zz = depth_average(z, szz, d.surface);
  d.stress_ratio = depth_average(z, profile_stress(profile, 0, 0), d.surface) / zz;
  d.friction = -depth_average(z, profile_stress_on_planes(profile, 0), d.surface) / zz;
  return d;
}

}  // namespace talus
