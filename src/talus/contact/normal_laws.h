#pragma once
// The registry of normal sub-models. A law is a struct with a `name` (its value of
// `contact.normal`), an `exponent` (F_n grows as delta^exponent) and `stiffness_scale(R*, delta)`
// = k_eff / k_n. Everything else follows from those: the force, the time step, the solved
// restitution damping, the elastic energy. To add a law, write its header and list it below.
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

#include "talus/contact/normal_hertz.h"
#include "talus/contact/normal_linear.h"

namespace talus {

template <class... Laws>
struct NormalLawList {
  static constexpr std::size_t size = sizeof...(Laws);

  // Calls f(Law{}) for the law with index `law` (0 if out of range).
  template <class F>
  static decltype(auto) visit(std::uint8_t law, F&& f) {
    return visit_from<Laws...>(law, 0, f);
  }
  static std::vector<std::string> names() { return {std::string(Laws::name)...}; }

 private:
  template <class First, class... Rest, class F>
  static decltype(auto) visit_from(std::uint8_t law, std::uint8_t at, F& f) {
    if constexpr (sizeof...(Rest) == 0) {
      return f(First{});
    } else {
      if (law == at) return f(First{});
      return visit_from<Rest...>(law, static_cast<std::uint8_t>(at + 1), f);
    }
  }
};

using NormalLaws = NormalLawList<LinearNormal, HertzNormal>;  // index 0 is the default

// The index of a law in NormalLaws.
template <class Law>
constexpr std::uint8_t normal_law_index() {
  return []<class... L>(NormalLawList<L...>) {
    std::uint8_t k = 0, found = 0;
    ((std::is_same_v<L, Law> ? (found = k, ++k) : ++k), ...);
    return found;
  }(NormalLaws{});
}

inline double normal_stiffness_scale(std::uint8_t law, double reduced_radius, double overlap) {
  return NormalLaws::visit(law, [&](auto l) { return decltype(l)::stiffness_scale(reduced_radius, overlap); });
}
inline double normal_exponent(std::uint8_t law) {
  return NormalLaws::visit(law, [](auto l) { return decltype(l)::exponent; });
}

}  // namespace talus
