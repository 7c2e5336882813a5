#pragma once
// Height of the pile along the width of the channel, with its spread.
// Huet et al. 2021, Sec. III C, Fig. 5(b): H is the mean height along the width; the first and
// third quartiles give the error bars of H0/H_inf (Fig. 11).
#include <vector>

#include "talus/analysis/collapse_image.h"

namespace talus::collapse {

struct HeightProfile {
  std::vector<double> y;   ///< m, pixel-row centres across the width
  std::vector<double> h;   ///< m, pile height above the ground at each y (0 where bare)
  double mean = 0;         ///< m, the height H the paper reports
  double q1 = 0;           ///< m, first quartile of h(y)
  double median = 0;       ///< m
  double q3 = 0;           ///< m, third quartile of h(y)
};

// h(y) = highest surface point, over the top-view columns whose centre lies in [x_min, x_max],
// minus ground_z: what a camera looking along x at that band of the pile sees, without the
// pixel rounding in z. A band narrower than a pixel uses the column holding its middle.
HeightProfile height_along_width(const ProjectionImage& top_view, double x_min, double x_max,
                                 double ground_z = 0);

// Quantile q in [0, 1] with linear interpolation between order statistics (numpy's default).
double quantile(std::vector<double> values, double q);

}  // namespace talus::collapse
