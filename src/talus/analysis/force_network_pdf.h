#pragma once
// Probability density of the scaled contact force F_c / <F_c>, on linear or logarithmic bins.
// Huet et al. 2021, Sec. IV C 1, Fig. 15 (a) linear and (b) logarithmic scale.
#include <cstddef>
#include <vector>

namespace talus {

struct ForcePdf {
  std::vector<double> edges;     ///< bin edges in F / <F> (bins + 1 values)
  std::vector<double> centres;   ///< bin centres: arithmetic (linear bins) or geometric (log bins)
  std::vector<double> density;   ///< per unit of F / <F>; sum(density * width) = share of samples binned
  double mean_force = 0;         ///< N, <F_c> over all samples
  std::size_t samples = 0;       ///< forces given
  std::size_t outside = 0;       ///< forces outside [edges.front(), edges.back()] (zeros, on log bins)
};

// Bins of equal width on [0, max_ratio]; max_ratio <= 0 takes the largest F / <F>.
ForcePdf force_pdf_linear(const std::vector<double>& forces, int bins, double max_ratio = 0);

// Bins of equal width in log(F / <F>) on [min_ratio, max_ratio]; a bound <= 0 takes the smallest
// positive, or the largest, F / <F>. The density is still per unit of F / <F>, as in Fig. 15(b).
ForcePdf force_pdf_log(const std::vector<double>& forces, int bins, double min_ratio = 0, double max_ratio = 0);

}  // namespace talus
