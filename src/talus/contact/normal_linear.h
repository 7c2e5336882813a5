#pragma once
// The linear normal spring: F_n = k_n delta (Huet et al. 2021, Eq. 5; Weinhart et al. 2012, Eq. 3).
#include <string_view>

namespace talus {

struct LinearNormal {
  static constexpr std::string_view name = "linear";
  static constexpr double exponent = 1;  ///< F_n grows as delta^exponent
  // k_eff / k_n, the stiffness of this contact relative to the parameter k_n (N/m).
  static double stiffness_scale(double /*reduced_radius*/, double /*overlap*/) { return 1.0; }
};

}  // namespace talus
