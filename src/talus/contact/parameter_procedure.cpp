#include "talus/contact/parameter_procedure.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace talus::params {

using std::numbers::pi;

double reduced_mass(double inv_mass_i, double inv_mass_j) { return 1.0 / (inv_mass_i + inv_mass_j); }

double contact_time(double kn, double m, double e) {
  const double ln_e = std::log(e);
  return std::sqrt(m * (pi * pi + ln_e * ln_e) / kn);
}

double restitution(double kn, double eta_n, double m) {
  const double gamma = eta_n / (2 * m);
  const double omega0_sq = kn / m;
  if (gamma * gamma >= omega0_sq) return 0.0;  // overdamped: no rebound
  return std::exp(-gamma * pi / std::sqrt(omega0_sq - gamma * gamma));
}

double normal_stiffness_for_overlap(double m, double v_max, double delta_max, double e) {
  if (!(e > 0 && e < 1)) throw std::invalid_argument("restitution must lie in (0, 1)");
  const double zeta = -pi / std::log(e);  // Eq. (15)
  const double a = std::atan(zeta);
  const double s = v_max / delta_max * std::exp(-a / zeta) * std::sin(a);
  return m * (1 + 1 / (zeta * zeta)) * s * s;
}

double max_overlap(double kn, double m, double v_max, double e) {
  const double zeta = -pi / std::log(e);
  const double omega0 = std::sqrt(kn / m);
  const double omega = omega0 / std::sqrt(1 + 1 / (zeta * zeta));  // Eq. (14) with gamma = omega/zeta
  const double gamma = omega / zeta;
  const double t_max = std::atan(zeta) / omega;                     // Eq. (15)
  return v_max / omega * std::exp(-gamma * t_max) * std::sin(omega * t_max);  // Eq. (13)
}

double normal_damping(double kn, double m, double e) {
  const double ln_e = std::log(e);
  return -2 * m * std::sqrt(kn / m) * ln_e / std::sqrt(pi * pi + ln_e * ln_e);
}

TangentialCoefficients pournin_tangential(double kn, double eta_n, double m, double ri, double ii,
                                          double rj, double ij, double en, double et) {
  const double shape = 1 + m * (ri * ri / ii + (ij > 0 ? rj * rj / ij : 0.0));
  const double ln_en = std::log(en), ln_et = std::log(et);
  return {kn / shape * (pi * pi + ln_et * ln_et) / (pi * pi + ln_en * ln_en),  // Eq. (18)
          eta_n / shape * ln_et / ln_en};                                      // Eq. (19)
}

RollingCoefficients rolling_from_normal(double kn, double eta_n, double mu_r, double radius) {
  const double scale = 3 * mu_r * mu_r * radius * radius;
  return {scale * kn, scale * eta_n};
}

double collision_time(double kn, double gamma_n, double m) {
  const double g = gamma_n / (2 * m);
  const double w2 = kn / m - g * g;
  if (w2 <= 0) throw std::invalid_argument("overdamped contact: no collision time");
  return pi / std::sqrt(w2);
}

double restitution_from_collision(double kn, double gamma_n, double m) {
  return std::exp(-collision_time(kn, gamma_n, m) * gamma_n / (2 * m));
}

}  // namespace talus::params
