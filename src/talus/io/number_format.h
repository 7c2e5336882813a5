#pragma once
// Shortest text that reads back to the same number (std::to_chars), used wherever Talus writes
// numbers for people or programs: CSV cells, error messages. Never loses a bit, never pads.
#include <cstdint>
#include <string>

namespace talus::io {

// Shortest round-trip form: 0.1 -> "0.1", 1.0/3 -> "0.3333333333333333", -3.0 -> "-3",
// infinities and NaN -> "inf", "-inf", "nan".
std::string format_double(double value);
std::string format_int(std::int64_t value);

// Append variants that avoid a temporary string in hot writers.
void append_double(std::string& out, double value);
void append_int(std::string& out, std::int64_t value);

}  // namespace talus::io
