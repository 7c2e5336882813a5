#pragma once
// Gauss-Legendre rules on [-1, 1] for the coarse-graining line integrals that have no
// closed form (the Lucy function off the axis, and the cross-check of the exact Gaussian).
#include <vector>

namespace talus {

struct GaussLegendreRule {
  std::vector<double> nodes;    ///< abscissae in [-1, 1], ascending
  std::vector<double> weights;  ///< summing to 2
};

// The n-point rule (exact for polynomials of degree 2n-1), nodes found by Newton iteration
// on P_n to machine precision. Rules for n <= 32 are cached; the reference is valid forever.
const GaussLegendreRule& gauss_legendre(int n);

}  // namespace talus
