#pragma once
// summary.json and other JSON results, written atomically (see atomic_file.h).
#include <cmath>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>

namespace talus::io {

// Pretty-printed with `indent` spaces and a final newline. Doubles are printed in the
// shortest form that reads back to the same bits (nlohmann's Grisu2, e.g. 0.1 -> 0.1);
// NaN and infinities have no JSON form and become null. Invalid UTF-8 in strings is
// replaced by U+FFFD rather than failing at the end of a long run.
void write_json(const std::filesystem::path& path, const nlohmann::json& value, int indent = 2);
// Throws std::runtime_error naming the file when it cannot be read or is not JSON.
nlohmann::json read_json(const std::filesystem::path& path);

// `value` with every NaN and infinity replaced by the string "nan", "inf" or "-inf": for records
// of a state that blew up, where a null would read as "not measured".
nlohmann::json non_finite_as_text(nlohmann::json value);

// A time that may be "never" (+inf), which JSON cannot hold: written as null, read back as +inf.
inline nlohmann::json time_or_null(double t) { return std::isfinite(t) ? nlohmann::json(t) : nlohmann::json(); }
inline double null_or_time(const nlohmann::json& j) {
  return j.is_null() ? std::numeric_limits<double>::infinity() : j.get<double>();
}

}  // namespace talus::io
