#include "talus/io/number_format.h"

#include <charconv>

namespace talus::io {

void append_double(std::string& out, double value) {
  char buf[32];  // the longest shortest-form double, "-2.2250738585072014e-308", is 24 chars
  const auto res = std::to_chars(buf, buf + sizeof(buf), value);
  out.append(buf, res.ptr);
}

void append_int(std::string& out, std::int64_t value) {
  char buf[24];
  const auto res = std::to_chars(buf, buf + sizeof(buf), value);
  out.append(buf, res.ptr);
}

std::string format_double(double value) {
  std::string out;
  append_double(out, value);
  return out;
}

std::string format_int(std::int64_t value) {
  std::string out;
  append_int(out, value);
  return out;
}

}  // namespace talus::io
