#pragma once
// Range checks for numbers read from a scenario file. A getter that takes a Check reports a
// violation with the key's file and line, so a bad value is caught where it is written, not
// as a NaN a thousand steps later.
#include <optional>
#include <string>

namespace talus::io {

struct Check {
  enum class Kind { None, Positive, NonNegative, InRange };
  Kind kind = Kind::None;
  double lo = 0;  ///< inclusive lower bound, InRange only
  double hi = 0;  ///< inclusive upper bound, InRange only

  // "positive", "non-negative", "in [0, 1]"; empty for None.
  std::string describe() const;
  // The complaint for `value`, e.g. "must be positive, got -3"; nothing if it passes. Every
  // check, None included, refuses inf and nan.
  std::optional<std::string> violation(double value) const;
};

inline constexpr Check positive{Check::Kind::Positive};
inline constexpr Check non_negative{Check::Kind::NonNegative};
constexpr Check in_range(double lo, double hi) { return Check{Check::Kind::InRange, lo, hi}; }

}  // namespace talus::io
