// (e) Depth averages, flow height (Weinhart et al. 2012, Eqs. 33 and 42) and balance residuals
// on analytic profiles.
#include <cmath>

#include <gtest/gtest.h>

#include "talus/analysis/cg_balance.h"
#include "talus/analysis/depth_profile.h"

namespace talus {
namespace {

std::vector<double> linspace(double a, double b, int n) {
  std::vector<double> z(n);
  for (int k = 0; k < n; ++k) z[k] = a + (b - a) * k / (n - 1);
  return z;
}

double shape_factor(const std::vector<double>& z, const std::vector<double>& u, const FlowSurface& fs) {
  std::vector<double> u2(u.size());
  for (std::size_t k = 0; k < u.size(); ++k) u2[k] = u[k] * u[k];
  const double mean = depth_average(z, u, fs);
  return depth_average(z, u2, fs) / (mean * mean);
}

TEST(CoarseGrainDepth, ShapeFactorOfKnownProfiles) {
  const FlowSurface fs{0, 2};
  const std::vector<double> z = linspace(0, 2, 4001);
  std::vector<double> bagnold(z.size()), linear(z.size()), plug(z.size(), 3.0);
  for (std::size_t k = 0; k < z.size(); ++k) {
    bagnold[k] = 1 - std::pow(1 - z[k] / 2, 1.5);  // u mean = 3/5, mean(u^2) = 9/20
    linear[k] = z[k];
  }
  EXPECT_NEAR(depth_average(z, bagnold, fs), 0.6, 1e-6);
  EXPECT_NEAR(shape_factor(z, bagnold, fs), 1.25, 1e-6);
  EXPECT_NEAR(shape_factor(z, linear, fs), 4.0 / 3.0, 1e-6);
  EXPECT_NEAR(shape_factor(z, plug, fs), 1.0, 1e-12);
}

// Eq. 42 on a lithostatic profile (max below b, linear to zero at s) recovers b and s exactly.
TEST(CoarseGrainDepth, FlowSurfaceOfALinearStressProfile) {
  const double b = 0.3, s = 2.1, top = 5;
  const std::vector<double> z = linspace(-1, 3, 1001);
  std::vector<double> szz(z.size());
  for (std::size_t k = 0; k < z.size(); ++k) szz[k] = top * std::clamp((s - z[k]) / (s - b), 0.0, 1.0);
  const FlowSurface fs = flow_surface(z, szz);
  EXPECT_NEAR(fs.base, b, 1e-12);
  EXPECT_NEAR(fs.surface, s, 1e-12);
  EXPECT_NEAR(fs.height(), s - b, 1e-12);
}

TEST(CoarseGrainDepth, IntegrateProfileExtendsEndValues) {
  const std::vector<double> z{0, 1, 2}, q{1, 3, 5};
  EXPECT_NEAR(integrate_profile(z, q, 0, 2), 6, 1e-15);
  EXPECT_NEAR(integrate_profile(z, q, 0.5, 1.5), 3, 1e-15);
  EXPECT_NEAR(integrate_profile(z, q, -1, 3), 12, 1e-15);
  EXPECT_NEAR(integrate_profile(z, q, 2, 0), -6, 1e-15);
}

// A steady uniform flow down a slope theta, built as a profile: constant density, Bagnold
// velocity, lithostatic stresses with sigma_xx = K0 sigma_zz. depth_averages must return
// h, rho, alpha = 5/4, K = K0, mu = tan(theta), and both balances must vanish.
TEST(CoarseGrainDepth, SteadyInclinedFlowProfile) {
  const double theta = 24 * M_PI / 180, g = 9.81, rho = 0.6, h = 10, K0 = 1.1, umax = 2;
  const Vec3 gravity{g * std::sin(theta), 0, -g * std::cos(theta)};
  CgFields prof;
  prof.grid = CgGrid::depth(-2, 12, 1401);
  prof.values.resize(prof.grid.size());
  for (int k = 0; k < prof.grid.size(); ++k) {
    const double z = prof.grid.point(k).z;
    CgValues& v = prof.values[k];
    const bool inside = z >= 0 && z <= h;
    const double depth = std::clamp(h - z, 0.0, h);
    v.density = inside ? rho : 0;
    const double u = inside ? umax * (1 - std::pow(1 - z / h, 1.5)) : 0;
    v.momentum = {v.density * u, 0, 0};
    v.momentum_flux(0, 0) = v.density * u * u;
    v.contact_stress(2, 2) = rho * g * std::cos(theta) * depth;
    v.contact_stress(0, 2) = v.contact_stress(2, 0) = -rho * g * std::sin(theta) * depth;
    v.contact_stress(0, 0) = K0 * v.contact_stress(2, 2);
  }
  const DepthAverages d = depth_averages(prof);
  EXPECT_NEAR(d.surface.base, 0, 1e-9);
  EXPECT_NEAR(d.surface.surface, h, 1e-9);
  EXPECT_NEAR(d.density, rho, 1e-9);
  EXPECT_NEAR(d.velocity, 0.6 * umax, 1e-5);
  EXPECT_NEAR(d.shape_factor, 1.25, 1e-5);
  EXPECT_NEAR(d.stress_ratio, K0, 1e-12);
  EXPECT_NEAR(d.friction, std::tan(theta), 1e-12);
  const BalanceResiduals r = steady_balance(prof, gravity);
  for (std::size_t k = 0; k < r.z.size(); ++k) {
    EXPECT_EQ(r.mass[k], 0);
    if (r.z[k] > 0.02 && r.z[k] < h - 0.02) {  // away from the jumps of the density at b and s
      EXPECT_NEAR(r.momentum[k].x, 0, 1e-9) << r.z[k];
      EXPECT_NEAR(r.momentum[k].z, 0, 1e-9) << r.z[k];
    }
  }
}

}  // namespace
}  // namespace talus
