#pragma once
// Depth-averaged quantities of a steady uniform flow from its depth profile (Weinhart et al.
// 2012, Sects. 4.1, 7 and 9): flow base and surface from sigma_zz (Eq. 42), depth averages
// (Eq. 33), and the closure quantities rho, u, alpha, K and mu of the shallow-layer Eqs. 34.
// Plain-vector forms take any profile (z ascending); depth_averages() reads a CgFields profile.
#include <vector>

#include "talus/analysis/cg_fields.h"

namespace talus {

struct FlowSurface {
  double base = 0;     ///< m, b
  double surface = 0;  ///< m, s
  double height() const { return surface - base; }  ///< m, h = s - b
};

// Eq. 42: z1, z2 where sigma_zz crosses (1 - kappa) max and kappa max (linearly interpolated
// between grid points), then b = z1 - kappa/(1 - 2 kappa)(z2 - z1), s = z2 + ... — the heights
// where the line through (z1, z2) reaches max and 0 (derived: z1 = b + kappa h, z2 = s - kappa h).
// z1 is searched upward from the maximum: with boundary stress ending at the contact points,
// sigma_zz falls to zero again below the base instead of staying at its maximum.
FlowSurface flow_surface(const std::vector<double>& z, const std::vector<double>& sigma_zz,
                         double kappa = 0.01);

// ∫_from^to q dz of the piecewise-linear interpolant of (z, q), constant beyond the ends.
double integrate_profile(const std::vector<double>& z, const std::vector<double>& q, double from, double to);

// Eq. 33: (1/h) ∫_b^s q dz.
double depth_average(const std::vector<double>& z, const std::vector<double>& q, const FlowSurface& fs);

struct DepthAverages {
  FlowSurface surface;
  double density = 0;       ///< kg/m^3, rho bar
  double velocity = 0;      ///< m/s, u bar = (1/h) ∫ u dz, u = p_x / rho
  double shape_factor = 0;  ///< alpha = mean(u^2) / u bar^2 (Sect. 4.1)
  double stress_ratio = 0;  ///< K = sigma_xx bar / sigma_zz bar
  double friction = 0;      ///< mu = -sigma_xz bar / sigma_zz bar
};

// From a depth profile (a CgGrid::depth grid), x downslope and z normal to the base. sigma_xz
// and sigma_zz are the base-extended ones (profile_stress_on_planes), as in the paper, so that
// sigma_zz is monotonic and Eq. 42 finds the base at the basal contacts. The friction carries
// a minus sign because compressive-positive sigma_xz is negative when the
// flow above drags the flow below down +x (the paper's Fig. 7 plots -sigma_xz); in steady flow
// mu = tan(theta) (Sect. 7).
DepthAverages depth_averages(const CgFields& profile, double kappa = 0.01);

// The z coordinates of a depth profile, and one stress component (row, col) along it.
std::vector<double> profile_z(const CgFields& profile);
std::vector<double> profile_stress(const CgFields& profile, int row, int col);

// sigma_(row, z) with the stress of the basal contacts continued below the contact points, as
// in the paper's Eq. 32 (line to infinity): sigma_rz(z) + ∫_z^top t_b,r dz'. Derivation: for a
// flowing particle above its contact point, f_r b_z ∫_1^inf W(z - z_i + s b_z) ds =
// f_r ∫_{-inf}^{c_z} W(z - u) du = ∫_z^inf f_r W(z' - c_z) dz'. Exact up to the trapezoid rule
// on the grid. For steady flow this is the weight above z (Eq. 41) all the way down.
std::vector<double> profile_stress_on_planes(const CgFields& profile, int row);

}  // namespace talus
