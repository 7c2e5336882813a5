// Coarse-graining functions: normalisation with the cutoff, and the line integral of the
// contact stress (exact erf form against Gauss-Legendre quadrature).
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "talus/analysis/cg_function.h"
#include "talus/analysis/cg_quadrature.h"

namespace talus {
namespace {

// ∫_{r<c} W d^D r as a radial integral by 40-point Gauss-Legendre on each of 8 shells: an
// independent check of the closed-form normalisations.
double radial_mass(const CgFunction& f) {
  const double shell[4] = {0, 2, 2 * M_PI, 4 * M_PI};  // surface of the unit sphere in D dims
  const GaussLegendreRule& rule = gauss_legendre(32);
  double sum = 0;
  const int pieces = 8;
  for (int p = 0; p < pieces; ++p) {
    const double a = f.cutoff * p / pieces, b = f.cutoff * (p + 1) / pieces;
    for (std::size_t k = 0; k < rule.nodes.size(); ++k) {
      const double r = 0.5 * (a + b) + 0.5 * (b - a) * rule.nodes[k];
      sum += 0.5 * (b - a) * rule.weights[k] * std::pow(r, f.dim - 1) * f.value(r * r);
    }
  }
  return shell[f.dim] * sum;
}

TEST(CoarseGrainFunction, GaussLegendreIsExactForPolynomials) {
  for (int n : {1, 2, 5, 8, 16, 32}) {
    const GaussLegendreRule& r = gauss_legendre(n);
    double s = 0, m = 0;
    for (int k = 0; k < n; ++k) s += r.weights[k], m += r.weights[k] * std::pow(r.nodes[k], 2 * n - 2);
    EXPECT_NEAR(s, 2, 1e-14) << n;
    EXPECT_NEAR(m, 2.0 / (2 * n - 1), 1e-14) << n;  // ∫ x^(2n-2) dx
  }
}

TEST(CoarseGrainFunction, IntegratesToOneIncludingTheCutoff) {
  for (int dim = 1; dim <= 3; ++dim) {
    EXPECT_NEAR(radial_mass(CgFunction::gaussian(0.7, dim)), 1, 1e-13) << dim;
    EXPECT_NEAR(radial_mass(CgFunction::gaussian(0.7, dim, 1.3)), 1, 1e-13) << dim;
    EXPECT_NEAR(radial_mass(CgFunction::lucy(1.9, dim)), 1, 1e-13) << dim;
  }
  // Beyond the cutoff W vanishes; inside it is the renormalised Gaussian.
  const CgFunction g = CgFunction::gaussian(1, 1);
  EXPECT_EQ(g.value(9.0), 0);
  EXPECT_GT(g.value(8.99), 0);
  EXPECT_NEAR(g.value(0), 1 / (std::sqrt(2 * M_PI) * std::erf(3 / std::sqrt(2.0))), 1e-15);
}

// (d) The closed-form Gaussian line integral against quadrature, in 1, 2 and 3 dimensions,
// for random segments that start, end or pass inside and outside the cutoff ball.
TEST(CoarseGrainFunction, GaussianLineIntegralMatchesQuadrature) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int dim = 1; dim <= 3; ++dim) {
    const CgFunction f = CgFunction::gaussian(0.4, dim);
    double worst = 0;
    for (int trial = 0; trial < 2000; ++trial) {
      Vec3 a{u(rng), u(rng), u(rng)}, b{u(rng), u(rng), u(rng)};
      a *= 1.6, b *= 1.2;
      for (int k = dim; k < 3; ++k) a[k] = b[k] = 0;
      const double exact = cg_line_integral(f, a, b);
      const double quad = cg_line_integral_quadrature(f, a, b, 16);
      worst = std::max(worst, std::abs(exact - quad) / f.norm);
    }
    // Relative to the peak of W: 16 points per half-chord reach round-off.
    EXPECT_LT(worst, 1e-10) << "dim " << dim;
  }
}

// In 1D the exact form reduces to an erf difference that can be written down directly.
TEST(CoarseGrainFunction, OneDimensionalLineIntegralIsTheErfDifference) {
  const double w = 0.2, c = 0.6;
  const CgFunction f = CgFunction::gaussian(w, 1, c);
  const auto cdf = [&](double x) {  // ∫_{-c}^{x} W, clamped
    x = std::clamp(x, -c, c);
    return f.norm * w * std::sqrt(M_PI / 2) * (std::erf(x / (std::sqrt(2.0) * w)) + std::erf(c / (std::sqrt(2.0) * w)));
  };
  for (double z = -2; z <= 2; z += 0.01) {
    // W(z - z_i + s (z_i - z_j)) for z_i = 1, z_j = -1: (1/2) ∫_{-1}^{1} W(z - u) du.
    const double expect = 0.5 * (cdf(z + 1) - cdf(z - 1));
    EXPECT_NEAR(cg_line_integral(f, {0, 0, z - 1}, {0, 0, 2}), expect, 1e-14) << z;
  }
}

// A reference for any kernel: 64 pieces of 32-point Gauss-Legendre.
double composite_line_integral(const CgFunction& f, const Vec3& a, const Vec3& b) {
  double sum = 0;
  for (int p = 0; p < 64; ++p) sum += cg_line_integral_quadrature(f, a + b * (p / 64.0), b / 64.0, 32) / 64.0;
  return sum;
}

// The closed form for Lucy (polynomial + asinh), including segments short enough to take the
// quadrature branch.
TEST(CoarseGrainFunction, LucyLineIntegralMatchesReference) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int dim = 1; dim <= 3; ++dim) {
    const CgFunction f = CgFunction::lucy(1.3, dim);
    double worst = 0;
    for (int trial = 0; trial < 2000; ++trial) {
      Vec3 a{u(rng), u(rng), u(rng)}, b{u(rng), u(rng), u(rng)};
      if (trial % 4 == 0) b *= 1e-3;
      if (trial % 8 == 0) a *= 1e-3;
      for (int k = dim; k < 3; ++k) a[k] = b[k] = 0;
      worst = std::max(worst, std::abs(cg_line_integral(f, a, b) - composite_line_integral(f, a, b)) / f.norm);
    }
    EXPECT_LT(worst, 1e-12) << "dim " << dim;
  }
}

TEST(CoarseGrainFunction, ShortSegmentIsAPointAndDirectionDoesNotMatter) {
  const CgFunction f = CgFunction::gaussian(0.5, 3);
  const Vec3 a{0.3, -0.2, 0.4};
  EXPECT_NEAR(cg_line_integral(f, a, {0, 0, 0}), f.value(norm2(a)), 1e-15);
  // Over 1e-9 the integral is the midpoint value to (1e-9/w)^2.
  EXPECT_NEAR(cg_line_integral(f, a, {1e-9, 0, 0}), f.value(norm2(a + Vec3{0.5e-9, 0, 0})), 1e-15);
  EXPECT_NEAR(cg_line_integral(f, a, {1e-3, 2e-3, 0}), cg_line_integral_quadrature(f, a, {1e-3, 2e-3, 0}, 8), 1e-13);
  // Reversing the segment (start at the other end) gives the same integral.
  const Vec3 b{0.5, 0.7, -0.9};
  EXPECT_NEAR(cg_line_integral(f, a, b), cg_line_integral(f, a + b, -b), 1e-14);
}

}  // namespace
}  // namespace talus
