#pragma once
// The coarse-grained fields at one grid point and on a whole grid (Weinhart et al. 2012,
// Sect. 3.2). Stress sign: compression positive, sigma = sum f_ij (x) r_ij (...) + sum m v'v' W,
// as in the paper's results (Eq. 41: sigma_zz = ∫ rho g cos(theta) dz > 0; Fig. 7 plots
// -sigma_xz, which is negative for flow down +x). Momentum balance in this convention:
//   d(rho V)/dt = -div(rho V V + sigma) + rho g + t_b,
// with t_b the force density from the base (see boundary_force).
#include <vector>

#include <Eigen/Core>

#include "talus/analysis/cg_grid.h"
#include "talus/math/vec3.h"

namespace talus {

struct CgValues {
  double density = 0;                                   ///< kg/m^3, Eq. 13 (flowing particles)
  Vec3 momentum;                                        ///< kg/(m^2 s), Eq. 16
  Eigen::Matrix3d momentum_flux = Eigen::Matrix3d::Zero();    ///< Pa, sum m v v W = kinetic stress + rho V V
  Eigen::Matrix3d kinetic_stress = Eigen::Matrix3d::Zero();   ///< Pa, sum m v' v' W with v' = v - V(r) (Eqs. 29-30)
  Eigen::Matrix3d contact_stress = Eigen::Matrix3d::Zero();   ///< Pa, flowing-flowing contacts, line r_i..r_j (Eq. 32)
  Eigen::Matrix3d boundary_stress = Eigen::Matrix3d::Zero();  ///< Pa, flowing-fixed/wall contacts, line r_i..contact point
  Vec3 boundary_force;                                  ///< N/m^3, sum f_ik W(r - c_ik): the base's push on the flow

  // m/s, Eq. 17; zero where there is no mass.
  Vec3 velocity() const { return density > 0 ? momentum / density : Vec3{}; }
  // Pa, the total stress of Eq. 32 (with the boundary part ending at the contact point).
  Eigen::Matrix3d stress() const { return kinetic_stress + contact_stress + boundary_stress; }

  // Eqs. 29-30 evaluated pointwise: sum m (v - V)(v - V) W = sum m v v W - p p / rho, exact
  // because V(r) is the field value at r. Formed from the additive fields, so it must be formed
  // again whenever those are summed (over ranks, for instance).
  void form_kinetic_stress() {
    if (density <= 0) {
      kinetic_stress.setZero();
      return;
    }
    const Eigen::Vector3d p(momentum.x, momentum.y, momentum.z);
    kinetic_stress = momentum_flux - p * p.transpose() / density;
  }
};

struct CgFields {
  CgGrid grid;
  std::vector<CgValues> values;  ///< one per grid point, indexed as CgGrid::index
};

}  // namespace talus
