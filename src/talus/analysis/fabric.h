#pragma once
// Fabric anisotropy: the preferred directions of the branch vectors joining the centres of
// touching particles. Huet et al. 2021, Sec. IV C 2, Figs. 16-17: the branch vector is projected
// onto the vertical xz plane and its angle theta to the horizontal x axis is histogrammed;
// wall contacts are excluded.
#include <array>
#include <cstddef>
#include <vector>

#include "talus/analysis/force_network.h"

namespace talus {

struct FabricHistogram {
  std::vector<double> edges;     ///< rad, bin edges over [0, pi] (a branch vector has no sign)
  std::vector<double> centres;   ///< rad
  std::vector<double> density;   ///< per radian, integrates to 1; isotropy is flat at 1/pi
  std::size_t samples = 0;       ///< branch vectors binned (those along y, with no xz part, are skipped)
};

// theta = atan2(b_z, b_x) folded into [0, pi): 0 and pi are horizontal, pi/2 vertical.
FabricHistogram fabric_angle_histogram(const Snapshot& snapshot, int bins = 36,
                                       PairPoints points = PairPoints::EachPoint);

// Fabric tensor <n n> of the unit branch vectors (3D, trace 1), particle-particle contacts only.
using FabricTensor = std::array<std::array<double, 3>, 3>;
FabricTensor fabric_tensor(const Snapshot& snapshot, PairPoints points = PairPoints::EachPoint);

// The same in the xz plane, from unit projected branch vectors: phi = <n n> (2x2, trace 1).
// anisotropy = 2 (lambda_max - lambda_min): 0 for isotropy, 2 when all are aligned;
// direction = angle of the major eigenvector to x, in [0, pi).
struct PlaneFabric {
  double xx = 0, xz = 0, zz = 0;   ///< components of phi
  double anisotropy = 0;
  double direction = 0;            ///< rad
};
PlaneFabric fabric_xz(const Snapshot& snapshot, PairPoints points = PairPoints::EachPoint);

}  // namespace talus
