#pragma once
// The Hertz normal force between elastic spheres: F_n = 4/3 E* sqrt(R*) delta^(3/2), written as
// F_n = k_eff delta with k_eff = k_n a, k_n = 4/3 E* and a = sqrt(R* delta) the contact radius
// (Hertz 1882; Johnson, Contact Mechanics, 1985, Eq. 4.23).
#include <cmath>
#include <string_view>

namespace talus {

struct HertzNormal {
  static constexpr std::string_view name = "hertz";
  static constexpr double exponent = 1.5;
  // k_eff / k_n with k_n = 4/3 E* (Pa): the contact radius a, in m.
  static double stiffness_scale(double reduced_radius, double overlap) { return std::sqrt(reduced_radius * overlap); }
};

// Effective moduli of a contact between two bodies of one material (Young's modulus E, Pa;
// Poisson's ratio nu), or between a body of it and a rigid wall (Johnson 1985, Eqs. 4.22, 7.13):
// 1/E* = sum (1 - nu^2)/E, 1/G* = sum (2 - nu)/G, G = E / (2 (1 + nu)).
struct ElasticModuli {
  double effective_youngs = 0;  ///< E*, Pa
  double effective_shear = 0;   ///< G*, Pa
};

inline ElasticModuli elastic_moduli(double youngs, double poisson, bool rigid_partner) {
  const double sides = rigid_partner ? 1.0 : 2.0;
  const double shear = youngs / (2 * (1 + poisson));
  return {youngs / (sides * (1 - poisson * poisson)), shear / (sides * (2 - poisson))};
}

// The Hertz-Mindlin no-slip tangential stiffness is k_t = 8 G* a (Mindlin 1949): this factor
// times the contact radius a.
inline double mindlin_stiffness(const ElasticModuli& m) { return 8 * m.effective_shear; }
// k_n of the Hertz law: 4/3 E*.
inline double hertz_stiffness(const ElasticModuli& m) { return 4.0 / 3.0 * m.effective_youngs; }

}  // namespace talus
