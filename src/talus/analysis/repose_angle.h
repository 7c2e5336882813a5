#pragma once
// The angle of repose of a pile on a floor, from the particles (Huet et al. 2021, Appendix B 2,
// Fig. 23: repose angle of the pile left by a hopper discharge against mu_c).
//
// The free surface is sampled in bins along one horizontal axis: in each bin, the highest point
// of any particle (centre height plus radius) above the floor. The pile's apex splits the profile
// into two flanks; on each flank a straight line is fitted by least squares to the bins whose
// surface lies between `fit_low` and `fit_high` of the pile height, which leaves out the rounded
// apex and the toe where rolling particles spread. The repose angle of a flank is atan|slope|.
#include <vector>

#include "talus/analysis/snapshot.h"

namespace talus::repose {

struct ProfileSettings {
  int axis = 0;            ///< profile direction: 0 = x, 1 = y
  double floor = 0;        ///< m, height of the floor the pile rests on
  double bin = 0;          ///< m, bin width along `axis` (> 0)
  double fit_low = 0.2;    ///< share of the pile height: lowest surface point fitted
  double fit_high = 0.8;   ///< share of the pile height: highest surface point fitted
  Vec3 region_lo, region_hi;  ///< m, only particles whose centre lies in this box count
};

struct SurfaceProfile {
  std::vector<double> position;  ///< m, bin centres along the axis
  std::vector<double> height;    ///< m above the floor; 0 for an empty bin
};

struct FlankFit {
  double angle_deg = 0;  ///< repose angle, atan|slope| (NaN if fewer than 3 bins were fitted)
  double slope = 0;      ///< dh/dx of the fitted line
  double intercept = 0;  ///< m, height of the line at position 0
  int bins = 0;          ///< bins in the fit
};

struct ReposeResult {
  SurfaceProfile profile;
  double pile_height = 0;  ///< m, highest surface point above the floor
  double apex = 0;         ///< m, position of the highest bin along the axis
  FlankFit left, right;    ///< below and above the apex along the axis
  double angle_deg = 0;    ///< mean of the two flanks (one of them if the other failed; NaN if both)
  int particles = 0;       ///< particles in the region
};

SurfaceProfile surface_profile(const Snapshot& snapshot, const ProfileSettings& settings);

ReposeResult measure_repose(const Snapshot& snapshot, const ProfileSettings& settings);

}  // namespace talus::repose
