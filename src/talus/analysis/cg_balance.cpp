#include "talus/analysis/cg_balance.h"

#include <stdexcept>

#include "talus/analysis/depth_profile.h"

namespace talus {
namespace {

// dq/dz on a uniform grid: central inside, second-order one-sided at the ends.
std::vector<double> derivative(const std::vector<double>& q, double h) {
  const std::size_t n = q.size();
  std::vector<double> d(n);
  if (n < 3) throw std::invalid_argument("steady_balance: need >= 3 profile points");
  for (std::size_t k = 1; k + 1 < n; ++k) d[k] = (q[k + 1] - q[k - 1]) / (2 * h);
  d[0] = (-3 * q[0] + 4 * q[1] - q[2]) / (2 * h);
  d[n - 1] = (3 * q[n - 1] - 4 * q[n - 2] + q[n - 3]) / (2 * h);
  return d;
}

}  // namespace

BalanceResiduals steady_balance(const CgFields& profile, const Vec3& gravity) {
  BalanceResiduals r;
  r.z = profile_z(profile);
  const std::size_t n = r.z.size();
  const double h = profile.grid.spacing(2);
  std::vector<double> pz(n);
  for (std::size_t k = 0; k < n; ++k) pz[k] = profile.values[k].momentum.z;
  r.mass = derivative(pz, h);
  r.momentum.assign(n, Vec3{});
  for (int a = 0; a < 3; ++a) {
    std::vector<double> flux(n);
    for (std::size_t k = 0; k < n; ++k) {
      const CgValues& v = profile.values[k];
      flux[k] = v.momentum_flux(a, 2) + v.contact_stress(a, 2) + v.boundary_stress(a, 2);
    }
    const std::vector<double> dflux = derivative(flux, h);
    for (std::size_t k = 0; k < n; ++k) {
      const CgValues& v = profile.values[k];
      r.momentum[k][a] = -dflux[k] + v.density * gravity[a] + v.boundary_force[a];
    }
  }
  return r;
}

}  // namespace talus
