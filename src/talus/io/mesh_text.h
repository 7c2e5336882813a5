#pragma once
// Internal to the mesh file readers (triangle_mesh_file.h): the numbers of OBJ and ASCII STL.
#include <charconv>
#include <cmath>
#include <optional>
#include <string_view>

namespace talus::io {

// The whole token as a finite number (a leading '+' allowed, as C's strtod allows), or nothing.
inline std::optional<double> finite_number(std::string_view token) {
  if (token.starts_with('+')) token.remove_prefix(1);
  double value = 0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (error != std::errc() || end != token.data() + token.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

}  // namespace talus::io
