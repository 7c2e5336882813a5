#include "talus/analysis/cg_function.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "talus/analysis/cg_quadrature.h"

namespace talus {
namespace {

constexpr double kPi = std::numbers::pi;

// ∫_{r<c} exp(-r^2/2w^2) d^D r, derived by integrating in spherical shells (the paper's Eq. 14
// uses (sqrt(2 pi) w)^3, which is this without the cutoff).
double gaussian_mass(double w, double c, int dim) {
  const double u = c / w;
  const double tail = std::exp(-0.5 * u * u);
  switch (dim) {
    case 1: return std::sqrt(2 * kPi) * w * std::erf(u / std::sqrt(2.0));
    case 2: return 2 * kPi * w * w * (1 - tail);
    case 3:
      return std::pow(2 * kPi, 1.5) * w * w * w *
             (std::erf(u / std::sqrt(2.0)) - std::sqrt(2 / kPi) * u * tail);
  }
  throw std::invalid_argument("CgFunction: dim must be 1, 2 or 3");
}

// ∫_{r<c} (1 + 3r/c)(1 - r/c)^3 d^D r: 4c/5, pi c^2/5 and 16 pi c^3/105 (shell integrals of
// the quartic 1 - 6x^2 + 8x^3 - 3x^4).
double lucy_mass(double c, int dim) {
  switch (dim) {
    case 1: return 4 * c / 5;
    case 2: return kPi * c * c / 5;
    case 3: return 16 * kPi * c * c * c / 105;
  }
  throw std::invalid_argument("CgFunction: dim must be 1, 2 or 3");
}

// The part of the line a + s b, s in [0, 1], inside r < c, as t in [lo, hi], t being the
// distance along b from the point closest to the origin, at squared distance perp2.
struct Chord {
  double perp2 = 0, lo = 0, hi = 0, length = 0;  // m^2, m, m, m (length = |b|)
  bool empty = true;
};

Chord clip_chord(const Vec3& a, const Vec3& b, double c) {
  Chord ch;
  ch.length = norm(b);
  const Vec3 dir = b / ch.length;
  const double t0 = dot(a, dir);
  ch.perp2 = std::max(0.0, norm2(a) - t0 * t0);
  if (ch.perp2 >= c * c) return ch;
  const double half = std::sqrt(c * c - ch.perp2);
  ch.lo = std::max(t0, -half);
  ch.hi = std::min(t0 + ch.length, half);
  ch.empty = ch.hi <= ch.lo;
  return ch;
}

}  // namespace

CgFunction CgFunction::gaussian(double w, int dim, double c) {
  if (!(w > 0)) throw std::invalid_argument("CgFunction::gaussian: width must be positive");
  CgFunction f;
  f.kernel = CgKernel::gaussian;
  f.dim = dim;
  f.width = w;
  f.cutoff = c > 0 ? c : 3 * w;
  f.norm = 1 / gaussian_mass(w, f.cutoff, dim);
  return f;
}

CgFunction CgFunction::lucy(double c, int dim) {
  if (!(c > 0)) throw std::invalid_argument("CgFunction::lucy: cutoff must be positive");
  CgFunction f;
  f.kernel = CgKernel::lucy;
  f.dim = dim;
  f.width = c;
  f.cutoff = c;
  f.norm = 1 / lucy_mass(c, dim);
  return f;
}

double CgFunction::value(double r2) const {
  if (r2 >= cutoff * cutoff) return 0;
  if (kernel == CgKernel::gaussian) return norm * std::exp(-0.5 * r2 / (width * width));
  const double x = std::sqrt(r2) / cutoff;
  const double y = 1 - x;
  return norm * (1 + 3 * x) * y * y * y;
}

double cg_line_integral_quadrature(const CgFunction& f, const Vec3& a, const Vec3& b, int n) {
  const double len2 = norm2(b);
  if (len2 == 0) return f.value(norm2(a));
  // Work in s, not in the distance along b: for a short segment far from the origin the
  // distance would lose the segment length to round-off.
  const double sc = -dot(a, b) / len2;  // s of the point closest to the origin
  const double perp2 = std::max(0.0, norm2(a + sc * b));
  const double c2 = f.cutoff * f.cutoff;
  if (perp2 >= c2) return 0;
  const double ds = std::sqrt((c2 - perp2) / len2);
  const double lo = std::max(0.0, sc - ds), hi = std::min(1.0, sc + ds);
  if (hi <= lo) return 0;
  const GaussLegendreRule& rule = gauss_legendre(n);
  // Split at the closest point: Lucy has an |r|^3 term there that would spoil the accuracy.
  const double cuts[3] = {lo, std::clamp(sc, lo, hi), hi};
  double sum = 0;
  for (int piece = 0; piece < 2; ++piece) {
    const double mid = 0.5 * (cuts[piece] + cuts[piece + 1]);
    const double half = 0.5 * (cuts[piece + 1] - cuts[piece]);
    if (half <= 0) continue;
    for (int k = 0; k < n; ++k) sum += half * rule.weights[k] * f.value(norm2(a + (mid + half * rule.nodes[k]) * b));
  }
  return sum;
}

namespace {

// ∫ W dt along a line at squared distance p2 from the centre, as an antiderivative in t for
// the Lucy quartic W/N = 1 - 6x^2 + 8x^3 - 3x^4, x = sqrt(p2 + t^2)/c. The x^3 term uses
// ∫ (p^2 + t^2)^(3/2) dt = t (2t^2 + 5p^2) r / 8 + (3p^4/8) asinh(t/p) (integration by parts;
// asinh instead of log(t + r) so no cancellation for t < 0).
double lucy_antiderivative(double p2, double t, double c) {
  const double t2 = t * t, r = std::sqrt(p2 + t2), c2 = c * c;
  const double quad = (p2 * t + t * t2 / 3) / c2;
  const double quart = (p2 * p2 * t + 2 * p2 * t * t2 / 3 + t2 * t2 * t / 5) / (c2 * c2);
  const double p = std::sqrt(p2);
  const double cubic = (t * (2 * t2 + 5 * p2) * r / 8 + (p > 0 ? 3 * p2 * p2 / 8 * std::asinh(t / p) : 0)) / (c2 * c);
  return t - 6 * quad + 8 * cubic - 3 * quart;
}

}  // namespace

double cg_line_integral(const CgFunction& f, const Vec3& a, const Vec3& b) {
  // Below |b| = 1e-2 c (1e-2 w) the differences of antiderivatives would cancel; 8-point
  // Gauss-Legendre on each side of the closest point is then accurate to ~1e-15 of the peak.
  const double scale = f.kernel == CgKernel::gaussian ? f.width : f.cutoff;
  if (norm2(b) < 1e-4 * scale * scale) return cg_line_integral_quadrature(f, a, b, 8);
  const Chord ch = clip_chord(a, b, f.cutoff);
  if (ch.empty) return 0;
  if (f.kernel == CgKernel::lucy)
    return f.norm * (lucy_antiderivative(ch.perp2, ch.hi, f.cutoff) - lucy_antiderivative(ch.perp2, ch.lo, f.cutoff)) /
           ch.length;
  // W(perp2 + t^2) = W(perp2) exp(-t^2/2w^2), and ∫ exp(-t^2/2w^2) dt = w sqrt(pi/2) erf(t/(sqrt2 w)).
  const double w = f.width;
  const double k = 1 / (std::sqrt(2.0) * w);
  const double along = w * std::sqrt(kPi / 2) * (std::erf(ch.hi * k) - std::erf(ch.lo * k));
  const double across = ch.perp2 > 0 ? std::exp(-0.5 * ch.perp2 / (w * w)) : 1;  // 1 in 1D
  return f.norm * across * along / ch.length;
}

}  // namespace talus
