#pragma once
// What a chute study reports from a time-averaged depth profile (Weinhart et al. 2012,
// Sects. 7 and 9): flow height from sigma_zz (Eq. 42), depth averages and closure quantities
// (Eqs. 33-36, 51), and how well the profile obeys the steady balances (Eqs. 41, 44).
#include <optional>
#include <vector>

#include "talus/analysis/cg_fields.h"
#include "talus/analysis/depth_profile.h"
#include "talus/math/vec3.h"

namespace talus {

struct ChuteDepthSummary {
  DepthAverages averages;         ///< b, s, rho bar, u bar, alpha, K, mu (depth_profile.h)
  double angle = 0;               ///< rad, theta = atan(g_x / -g_z)
  double froude = 0;              ///< F = u bar / sqrt(g cos(theta) h) (Eq. 36)
  double volume_fraction = 0;     ///< rho bar / rho_p
  std::optional<double> bulk_volume_fraction;  ///< Eq. 51 / rho_p; needs h > 6 d
  double mu_base = 0;             ///< -sigma_xz / sigma_zz at z = b (base-extended stresses)
  double max_angle_deviation = 0; ///< rad, max |atan(mu(z)) - theta| over [b, s - 4 d] (Sect. 7: < 0.4 deg)
  double lithostatic_error = 0;   ///< max |sigma_zz - ∫_z rho g cos dz| / sigma_zz(b) over [b, s] (Sect. 7: < 0.5 %)
  double weight_error = 0;        ///< max sigma_zz (carried by the base) / (flowing weight per area * g cos theta) - 1
  double momentum_residual = 0;   ///< rms over [b, s] of |Eq. 44 residual| / (rho bar g) (Fig. 5: < 2 % at T >= 100)
  double mass_residual = 0;       ///< rms over [b, s] of |d(rho w)/dz| / (rho bar sqrt(g / d))
  double layering = 0;            ///< rms of rho / rho_bulk - 1 over the bulk [b + 2 d, s - 4 d]
};

// `particle_density` is rho_p, `diameter` d, `mass_per_area` the total mass of the flowing
// particles per unit base area (for the weight check; 0 skips it).
ChuteDepthSummary summarize_chute_profile(const CgFields& profile, const Vec3& gravity, double particle_density,
                                          double diameter, double mass_per_area, double kappa = 0.01);

// Eq. 51: (1/(h - 6d)) ∫_{b + 2d}^{s - 4d} rho dz; empty when h <= 6 d.
std::optional<double> bulk_density(const std::vector<double>& z, const std::vector<double>& rho, const FlowSurface& fs,
                                   double diameter);

}  // namespace talus
