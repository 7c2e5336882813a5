#include "talus/contact/head_on_impact.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "talus/contact/contact_law.h"

namespace talus::params {

namespace {

using std::numbers::pi;

// A linear spring-dashpot in units of 1/omega_0, x = exp(-zeta t) sin(w t) / w with
// w^2 = 1 - zeta^2. Unclamped, it leaves at w t = pi. Clamped, it leaves when x + 2 zeta x' = 0,
// at w t = atan2(2 zeta w, 2 zeta^2 - 1) (past critical damping w t = atanh(2 zeta w /
// (2 zeta^2 - 1)), w^2 = zeta^2 - 1); there x' = -x / (2 zeta), and in both cases the
// restitution is exp(-zeta t).
ImpactOutcome linear_impact(bool clamp, double zeta) {
  if (!clamp) {
    if (zeta >= 1) return {0, std::numeric_limits<double>::infinity()};  // overdamped: no rebound
    const double t = pi / std::sqrt(1 - zeta * zeta);
    return {std::exp(-zeta * t), t};
  }
  if (zeta == 0) return {1, pi};
  double t = 2;  // critical damping, the limit of both forms
  if (zeta < 1) {
    const double w = std::sqrt(1 - zeta * zeta);
    t = std::atan2(2 * zeta * w, 2 * zeta * zeta - 1) / w;
  } else if (zeta > 1) {
    const double w = std::sqrt(zeta * zeta - 1);
    t = std::atanh(2 * zeta * w / (2 * zeta * zeta - 1)) / w;
  }
  return {std::exp(-zeta * t), t};
}

ImpactOutcome integrated_impact(const ContactParams& p, double m, double radius, double speed, bool clamp) {
  const double exponent = normal_exponent(p.normal_law);
  const double k = p.normal_stiffness * normal_stiffness_scale(p.normal_law, radius, 1.0);  // F = K delta^p
  const double time_scale = std::pow(m / (k * std::pow(speed, exponent - 1)), 1 / (exponent + 1));
  const auto force = [&](double x, double v) {
    if (x <= 0) return 0.0;
    const ContactCoefficients c = contact_coefficients(p, m, radius, x);
    return c.kn * x + c.eta_n * v;
  };
  const auto accel = [&](double x, double v) {
    const double f = force(x, v);
    return -(clamp && f < 0 ? 0.0 : f) / m;
  };
  const double h = time_scale / 1024;
  double x = 0, v = speed, t = 0;
  for (int step = 0; step < (1 << 20); ++step) {
    const double k1x = v, k1v = accel(x, v);
    const double k2x = v + 0.5 * h * k1v, k2v = accel(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
    const double k3x = v + 0.5 * h * k2v, k3v = accel(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
    const double k4x = v + h * k3v, k4v = accel(x + h * k3x, v + h * k3v);
    const double xn = x + h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
    const double vn = v + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (xn <= 0) {
      const double s = x / (x - xn);
      return {-(v + s * (vn - v)) / speed, t + s * h};
    }
    if (clamp && vn < 0) {
      const double f0 = force(x, v), f1 = force(xn, vn);
      if (f1 <= 0) {
        const double s = f0 > f1 ? f0 / (f0 - f1) : 1.0;
        return {-(v + s * (vn - v)) / speed, t + s * h};
      }
    }
    x = xn;
    v = vn;
    t += h;
  }
  return {0, t};
}

}  // namespace

ImpactOutcome head_on_impact(const ContactParams& p, double m, double radius, double speed, bool clamp) {
  if (p.normal_law == normal_law_index<LinearNormal>()) {
    const double omega = std::sqrt(p.normal_stiffness / m);
    const ImpactOutcome o = linear_impact(clamp, p.normal_damping.at(m) / (2 * m * omega));
    return {o.restitution, o.duration / omega};
  }
  return integrated_impact(p, m, radius, speed, clamp);
}

double damping_for_restitution(std::uint8_t normal_law, bool clamp, double e) {
  if (!(e > 0 && e < 1)) throw std::invalid_argument("restitution must lie in (0, 1)");
  if (normal_law == normal_law_index<LinearNormal>() && !clamp) {
    const double ln_e = std::log(e);
    return -2 * ln_e / std::sqrt(pi * pi + ln_e * ln_e);  // Huet et al. 2021, Eq. (17), per sqrt(k_n m)
  }
  // The unit impact: k_n = m = R* = v0 = 1, so that c is the dashpot's coefficient itself.
  ContactParams unit;
  unit.normal_law = normal_law;
  unit.normal_stiffness = 1;
  unit.damping_scaling = DampingScaling::tsuji;
  const auto restitution = [&](double c) {
    unit.normal_damping.per_sqrt_reduced_mass = c;
    return head_on_impact(unit, 1, 1, 1, clamp).restitution;
  };
  // The restitution falls as the damping grows: bracket, then bisect.
  double lo = 0, hi = 1;
  while (restitution(hi) > e) {
    lo = hi;
    hi *= 2;
    if (hi > 1e12) throw std::invalid_argument("restitution out of reach");
  }
  const int iterations = normal_law == normal_law_index<LinearNormal>() ? 200 : 60;
  for (int k = 0; k < iterations && hi - lo > 1e-15 * hi; ++k) {
    const double mid = 0.5 * (lo + hi);
    (restitution(mid) > e ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace talus::params
