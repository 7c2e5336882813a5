#include "talus/io/value_check.h"

#include <cmath>

#include "talus/io/number_format.h"

namespace talus::io {

std::string Check::describe() const {
  switch (kind) {
    case Kind::None: return {};
    case Kind::Positive: return "positive";
    case Kind::NonNegative: return "non-negative";
    case Kind::InRange: return "in [" + format_double(lo) + ", " + format_double(hi) + "]";
  }
  return {};
}

std::optional<std::string> Check::violation(double value) const {
  // TOML spells inf and nan, but no scenario value means either: an infinite length or speed
  // would only resurface as a NaN, or as an overflowing cast, far from its line.
  if (!std::isfinite(value)) return "must be finite, got " + format_double(value);
  bool ok = true;
  switch (kind) {
    case Kind::None: ok = true; break;
    case Kind::Positive: ok = value > 0; break;
    case Kind::NonNegative: ok = value >= 0; break;
    case Kind::InRange: ok = value >= lo && value <= hi; break;
  }
  if (ok) return std::nullopt;
  return "must be " + describe() + ", got " + format_double(value);
}

}  // namespace talus::io
