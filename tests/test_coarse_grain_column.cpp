// (c) A static column under gravity: the coarse-grained sigma_zz must be the lithostatic
// weight (Weinhart et al. 2012, Eq. 41), the steady balances must hold, and the flow height of
// Eq. 42 must be the column height.
#include <cmath>

#include <gtest/gtest.h>

#include "talus/analysis/cg_balance.h"
#include "talus/analysis/coarse_grain.h"
#include "talus/analysis/depth_profile.h"
#include "test_coarse_grain_scenes.h"

namespace talus {
namespace {

constexpr int kLayers = 20;
constexpr double kG = 9.81, kMass = 0.3, kD = 1.0;

// Weight per area above z: sum m g ∫_{-inf}^{z_i} W(z - u) du, the exact ∫_z^inf rho g dz' of
// the cut Gaussian (erf), independent of the stress code.
double weight_above(const Snapshot& s, const CgFunction& f, double z) {
  const double k = 1 / (std::sqrt(2.0) * f.width), area = 4 * 4 * kD * kD;
  double sum = 0;
  for (const ParticleRecord& p : s.particles) {
    if (p.fixed) continue;
    const double x = std::clamp(p.position.z - z, -f.cutoff, f.cutoff);  // u - z from -c to x
    sum += p.mass * kG * f.norm * f.width * std::sqrt(M_PI / 2) * (std::erf(x * k) + std::erf(f.cutoff * k));
  }
  return sum / area;
}

TEST(CoarseGrainColumn, NormalStressIsLithostatic) {
  const Snapshot s = cg_test::static_column(4, 4, kLayers, kD, kMass, kG);
  for (double w : {0.25, 0.5, 1.0}) {
    const CgFunction f = CgFunction::gaussian(w, 1);
    const CgFields prof = coarse_grain(s, CgGrid::depth(0, kLayers + 3, 231), f);
    const double base_contact = kD, bottom_weight = weight_above(s, f, base_contact + f.cutoff);
    for (int k = 0; k < prof.grid.size(); ++k) {
      const double z = prof.grid.point(k).z;
      const double szz = prof.values[k].stress()(2, 2);
      // Above the reach of the base contacts sigma_zz is the weight above, exactly; the brief
      // asks for 1 %. Below, the stress ends at the base contact points (not the lithostatic
      // weight, which keeps rising), and the base pushes up through boundary_force instead.
      if (z >= base_contact + f.cutoff) EXPECT_NEAR(szz, weight_above(s, f, z), 1e-10 * bottom_weight) << z;
      EXPECT_NEAR(prof.values[k].stress()(0, 2), 0, 1e-12);
      EXPECT_NEAR(prof.values[k].stress()(0, 0), 0, 1e-12);
    }
  }
}

// Finite differences of the profile; the balance itself holds pointwise exactly.
double worst_momentum_z(const BalanceResiduals& r, double z_lo, double z_hi) {
  double worst = 0;
  for (std::size_t k = 0; k < r.z.size(); ++k)
    if (r.z[k] >= z_lo && r.z[k] <= z_hi) worst = std::max(worst, std::abs(r.momentum[k].z));
  return worst;
}

TEST(CoarseGrainColumn, SteadyBalancesHoldDownToTheBase) {
  const Snapshot s = cg_test::static_column(4, 4, kLayers, kD, kMass, kG);
  const double rho_g = kMass / (kD * kD * kD) * kG;
  // Lucy is C2, so the finite-difference residual converges (O(h^2)) everywhere, including at
  // the base where the boundary force balances the end of the stress.
  const CgFields lucy = coarse_grain(s, CgGrid::depth(0, kLayers + 3, 921), CgFunction::lucy(1.62, 1));
  const BalanceResiduals r = steady_balance(lucy, s.gravity);
  for (std::size_t k = 0; k < r.z.size(); ++k) {
    EXPECT_EQ(r.mass[k], 0);
    EXPECT_NEAR(r.momentum[k].x, 0, 1e-12);
  }
  EXPECT_LT(worst_momentum_z(r, 0, kLayers + 3), 1e-2 * rho_g);
  // The cut Gaussian jumps at r = c, so differences spike next to each jump: 1 % of rho g in
  // the bulk, 10 % at the base contacts' cutoff (z = d +- 3w), independent of h.
  const CgFields gauss = coarse_grain(s, CgGrid::depth(0, kLayers + 3, 461), CgFunction::gaussian(0.5, 1));
  const BalanceResiduals rg = steady_balance(gauss, s.gravity);
  EXPECT_LT(worst_momentum_z(rg, 3.5 * kD, kLayers * kD), 1.5e-2 * rho_g);
  EXPECT_LT(worst_momentum_z(rg, 0, kLayers + 3), 1.5e-1 * rho_g);
  // Without the boundary force the base would be out of balance by the column's weight.
  CgFields no_base = lucy;
  for (CgValues& v : no_base.values) v.boundary_force = {};
  EXPECT_GT(worst_momentum_z(steady_balance(no_base, s.gravity), 0, kLayers + 3), 1.0 * rho_g);
}

// With the basal stress continued below the contacts (the paper's form), sigma_zz is the
// weight above z everywhere, down through the base.
TEST(CoarseGrainColumn, BaseExtendedStressIsLithostaticEverywhere) {
  const Snapshot s = cg_test::static_column(4, 4, kLayers, kD, kMass, kG);
  const CgFunction f = CgFunction::lucy(1.62, 1);
  const CgFields prof = coarse_grain(s, CgGrid::depth(0, kLayers + 3, 461), f);
  const std::vector<double> z = profile_z(prof), szz = profile_stress_on_planes(prof, 2);
  const double total = kLayers * kMass * kG;
  for (std::size_t k = 0; k < z.size(); ++k) {
    std::vector<double> rho(z.size());
    for (std::size_t m = 0; m < z.size(); ++m) rho[m] = prof.values[m].density * kG;
    EXPECT_NEAR(szz[k], integrate_profile(z, rho, z[k], z.back()), 1e-3 * total) << z[k];
  }
}

TEST(CoarseGrainColumn, FlowHeightIsTheColumnHeight) {
  const Snapshot s = cg_test::static_column(4, 4, kLayers, kD, kMass, kG);
  // w = 0.25 d as in the paper's Sect. 7; the ends are smeared over ~w, which Eq. 42 sees.
  const CgFields prof = coarse_grain(s, CgGrid::depth(0, kLayers + 3, 461), CgFunction::gaussian(0.25, 1));
  const DepthAverages d = depth_averages(prof);
  // Base at the base contacts (z = d), surface at the top of the last sphere (z = (n + 1) d),
  // to within the layering of the discrete column (kappa = 1 % of 20 layers is 0.2 layer).
  EXPECT_NEAR(d.surface.base, kD, 0.15 * kD);
  EXPECT_NEAR(d.surface.surface, (kLayers + 1) * kD, 0.15 * kD);
  EXPECT_NEAR(d.surface.height(), kLayers * kD, 0.01 * kLayers * kD);
  EXPECT_NEAR(d.density, kMass / (kD * kD * kD), 0.02 * kMass);
  EXPECT_NEAR(d.stress_ratio, 0, 1e-12);
  EXPECT_NEAR(d.friction, 0, 1e-12);
  EXPECT_EQ(d.velocity, 0);
}

}  // namespace
}  // namespace talus
