#pragma once
// Balance checks on a depth profile of a flow uniform in x and y (Weinhart et al. 2012,
// Eqs. 18, 19 and 44). For steady flow both residuals vanish; their size measures how steady
// the flow is (the paper's Fig. 5) or how consistent the coarse graining is.
#include <vector>

#include "talus/analysis/cg_fields.h"
#include "talus/math/vec3.h"

namespace talus {

struct BalanceResiduals {
  std::vector<double> z;         ///< m, the profile's points
  std::vector<double> mass;      ///< kg/(m^3 s), d(rho V_z)/dz = -d rho/dt (Eq. 18)
  std::vector<Vec3> momentum;    ///< N/m^3, d(rho V)/dt from Eq. 44 in this code's sign convention
};

// Residuals of the steady balances, derivatives by second-order finite differences
// (one-sided at the ends):
//   mass:        d(rho V_z)/dz
//   momentum_a:  -d/dz (sigma_az + rho V_a V_z) + rho g_a + t_b,a   (a = x, y, z)
// with sigma compressive positive (cg_fields.h), so that at rest d sigma_zz/dz = rho g_z and
// d sigma_xz/dz = rho g_x. sigma_az + rho V_a V_z is taken as the momentum flux plus the contact
// and boundary stresses, which stays exact after time averaging (CgTimeAverage).
BalanceResiduals steady_balance(const CgFields& profile, const Vec3& gravity);

}  // namespace talus
