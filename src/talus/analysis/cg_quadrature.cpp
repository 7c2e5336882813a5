#include "talus/analysis/cg_quadrature.h"

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace talus {
namespace {

GaussLegendreRule make_rule(int n) {
  GaussLegendreRule rule;
  rule.nodes.resize(n);
  rule.weights.resize(n);
  for (int k = 0; k < (n + 1) / 2; ++k) {
    // Tricomi's initial guess for the k-th root, then Newton on the three-term recurrence.
    double x = std::cos(std::numbers::pi * (k + 0.75) / (n + 0.5));
    double dp = 1;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = x;
      for (int m = 2; m <= n; ++m) {
        const double p2 = ((2 * m - 1) * x * p1 - (m - 1) * p0) / m;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1);
      const double dx = p1 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    const double w = 2 / ((1 - x * x) * dp * dp);
    rule.nodes[k] = -x;
    rule.nodes[n - 1 - k] = x;
    rule.weights[k] = w;
    rule.weights[n - 1 - k] = w;
  }
  return rule;
}

}  // namespace

const GaussLegendreRule& gauss_legendre(int n) {
  if (n < 1 || n > 32) throw std::invalid_argument("gauss_legendre: n must be in 1..32");
  // Built once, before any thread asks (function-local static initialisation is thread-safe).
  static const std::array<GaussLegendreRule, 33> rules = [] {
    std::array<GaussLegendreRule, 33> r;
    for (int m = 1; m <= 32; ++m) r[m] = make_rule(m);
    return r;
  }();
  return rules[n];
}

}  // namespace talus
