#pragma once
// Runout distance of a collapsed pile from its top view.
// Huet et al. 2021, Sec. III C: L_inf is the leftmost pixel column (from the back wall) whose
// fraction of occupied pixels is below 10 %; the error bar spans the 20 % and 1 % thresholds.
#include <vector>

#include "talus/analysis/collapse_image.h"

namespace talus::collapse {

// Fraction of occupied pixels in each column of constant x (u) across the width (v).
struct IntensityProfile {
  std::vector<double> x;           ///< m, column centres
  std::vector<double> intensity;   ///< occupied fraction of each column, in [0, 1]
  double pixel = 0;                ///< m, column width
};

IntensityProfile column_intensity(const ProjectionImage& top_view);

// Left edge of the first column, scanning from the back wall towards larger x, whose intensity
// is below `threshold`: the boundary after the pile's last column at or above it. The scan starts
// at the first column reaching the threshold, so empty columns before the wall are skipped.
// Returns the far edge of the profile when no later column is below the threshold, and the
// near edge when no column reaches it.
double runout_at_threshold(const IntensityProfile& profile, double threshold);

struct RunoutThresholds {
  double nominal = 0.10;   ///< Huet et al. 2021, Sec. III C
  double low = 0.20;       ///< gives the lower end of the error bar
  double high = 0.01;      ///< gives the upper end of the error bar
};

struct Runout {
  double nominal = 0;              ///< m, L_inf at the 10 % threshold
  double low = 0;                  ///< m, at the 20 % threshold (low <= nominal)
  double high = 0;                 ///< m, at the 1 % threshold (high >= nominal)
  bool reached_frame_end = false;  ///< the 1 % runout hit the image edge: the frame is too short
  IntensityProfile profile;        ///< for the plot of Fig. 5(a)
};

Runout measure_runout(const ProjectionImage& top_view, const RunoutThresholds& thresholds = {});

}  // namespace talus::collapse
