#include "talus/io/value_check.h"

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
  // Written so that NaN fails every check: comparisons with NaN are false.
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
