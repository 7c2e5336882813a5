#include "talus/io/key_path.h"

#include <charconv>
#include <stdexcept>

namespace talus::io {

namespace {

bool is_name_char(char c) {
  return c != '.' && c != '[' && c != ']' && c != '=' && c != ' ' && c != '\t' && c != '\n';
}

}  // namespace

KeyPath parse_key_path(std::string_view text) {
  KeyPath path;
  std::size_t i = 0;
  if (text.empty()) throw std::invalid_argument("empty key");
  while (true) {
    const std::size_t start = i;
    while (i < text.size() && is_name_char(text[i])) ++i;
    if (i == start) throw std::invalid_argument("empty key name");
    path.emplace_back(std::string(text.substr(start, i - start)));
    while (i < text.size() && text[i] == '[') {
      const std::size_t close = text.find(']', i);
      if (close == std::string_view::npos) throw std::invalid_argument("missing ']'");
      std::size_t index = 0;
      const auto digits = text.substr(i + 1, close - i - 1);
      const auto res = std::from_chars(digits.data(), digits.data() + digits.size(), index);
      if (digits.empty() || res.ec != std::errc{} || res.ptr != digits.data() + digits.size())
        throw std::invalid_argument("bad index '" + std::string(digits) + "'");
      path.emplace_back(index);
      i = close + 1;
    }
    if (i == text.size()) return path;
    if (text[i] != '.') throw std::invalid_argument(std::string("unexpected '") + text[i] + "'");
    ++i;
  }
}

bool is_key_name(std::string_view name) {
  if (name.empty()) return false;
  for (char c : name)
    if (!is_name_char(c)) return false;
  return true;
}

std::string format_key_path(const KeyPath& path, std::size_t count) {
  std::string out;
  for (std::size_t k = 0; k < count && k < path.size(); ++k) {
    if (const auto* name = std::get_if<std::string>(&path[k])) {
      if (!out.empty()) out += '.';
      out += *name;
    } else {
      out += '[' + std::to_string(std::get<std::size_t>(path[k])) + ']';
    }
  }
  return out;
}

}  // namespace talus::io
