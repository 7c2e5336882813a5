#include "talus/io/scenario_values.h"

#include <cmath>

#include "talus/io/number_format.h"

namespace talus::io {

namespace {

// "a number", "a positive number", "a number in [0, 1]"; `article` is the one used when
// no adjective comes between it and the noun ("an integer" but "a positive integer").
std::string qualified(std::string_view article, std::string_view noun, const Check& check) {
  const std::string lead = article == "an" ? "a" : std::string(article);
  switch (check.kind) {
    case Check::Kind::None: return std::string(article) + " " + std::string(noun);
    case Check::Kind::Positive:
    case Check::Kind::NonNegative: return lead + " " + check.describe() + " " + std::string(noun);
    case Check::Kind::InRange:
      return std::string(article) + " " + std::string(noun) + " " + check.describe();
  }
  return {};
}

std::optional<double> number_of(const toml::node& node) {
  if (const auto* i = node.as_integer()) return static_cast<double>(i->get());
  if (const auto* f = node.as_floating_point()) return f->get();
  return std::nullopt;
}

// Numbers of an array, element by element, with `check` on each.
std::optional<std::vector<double>> numbers_of(const toml::array& array, const Check& check,
                                              const std::string& expected, std::string& why) {
  std::vector<double> values;
  values.reserve(array.size());
  for (std::size_t i = 0; i < array.size(); ++i) {
    const auto value = number_of(*array.get(i));
    if (!value) {
      why = "expected " + expected + ", element " + std::to_string(i) + " is " +
            describe(*array.get(i));
      return std::nullopt;
    }
    if (auto bad = check.violation(*value)) {
      why = "element " + std::to_string(i) + " " + *bad;
      return std::nullopt;
    }
    values.push_back(*value);
  }
  return values;
}

}  // namespace

std::string quote_value(std::string_view text) {
  constexpr std::size_t kMax = 40;
  std::string out = "\"";
  for (char c : text.substr(0, kMax)) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  if (text.size() > kMax) out += "...";
  return out + "\"";
}

std::string describe(const toml::node& node) {
  if (const auto* s = node.as_string()) return "a string (" + quote_value(s->get()) + ")";
  if (const auto* i = node.as_integer()) return format_int(i->get());
  if (const auto* f = node.as_floating_point()) return format_double(f->get());
  if (const auto* b = node.as_boolean()) return b->get() ? "true" : "false";
  if (const auto* a = node.as_array()) {
    if (a->is_array_of_tables()) return "an array of tables";
    return "an array of " + std::to_string(a->size()) + (a->size() == 1 ? " element" : " elements");
  }
  if (node.is_table()) return "a table";
  return "a date or time";
}

std::string expected_text(const Check& check, As<double>) { return qualified("a", "number", check); }
std::string expected_text(const Check& check, As<std::int64_t>) {
  return qualified("an", "integer", check);
}
std::string expected_text(const Check& check, As<int>) { return qualified("an", "integer", check); }
std::string expected_text(const Check&, As<bool>) { return "true or false"; }
std::string expected_text(const Check&, As<std::string>) { return "a string"; }
std::string expected_text(const Check& check, As<Vec3>) {
  return qualified("an array of 3", "numbers", check);
}
std::string expected_text(const Check& check, As<std::vector<double>>) {
  return qualified("an array of", "numbers", check);
}

std::optional<double> convert(const toml::node& node, const Check& check, std::string& why,
                              As<double>) {
  const auto value = number_of(node);
  if (!value) {
    why = "expected " + expected_text(check, As<double>{}) + ", got " + describe(node);
    return std::nullopt;
  }
  if (auto bad = check.violation(*value)) {
    why = *bad;
    return std::nullopt;
  }
  return value;
}

std::optional<std::int64_t> convert(const toml::node& node, const Check& check, std::string& why,
                                    As<std::int64_t>) {
  std::optional<std::int64_t> value;
  if (const auto* i = node.as_integer()) value = i->get();
  // A whole float is accepted (`steps = 1e6`); 2^63 itself is out of range, hence `<`.
  if (const auto* f = node.as_floating_point(); f && std::trunc(f->get()) == f->get() &&
                                                f->get() >= -0x1p63 && f->get() < 0x1p63)
    value = static_cast<std::int64_t>(f->get());
  if (!value) {
    why = "expected " + expected_text(check, As<std::int64_t>{}) + ", got " + describe(node);
    return std::nullopt;
  }
  if (auto bad = check.violation(static_cast<double>(*value))) {
    why = *bad;
    return std::nullopt;
  }
  return value;
}

std::optional<int> convert(const toml::node& node, const Check& check, std::string& why, As<int>) {
  const auto wide = convert(node, check, why, As<std::int64_t>{});
  if (!wide) return std::nullopt;
  if (*wide < std::numeric_limits<int>::min() || *wide > std::numeric_limits<int>::max()) {
    why = "must fit a 32-bit integer, got " + format_int(*wide);
    return std::nullopt;
  }
  return static_cast<int>(*wide);
}

std::optional<bool> convert(const toml::node& node, const Check&, std::string& why, As<bool>) {
  if (const auto* b = node.as_boolean()) return b->get();
  why = "expected true or false, got " + describe(node);
  return std::nullopt;
}

std::optional<std::string> convert(const toml::node& node, const Check&, std::string& why,
                                   As<std::string>) {
  if (const auto* s = node.as_string()) return s->get();
  why = "expected a string, got " + describe(node);
  return std::nullopt;
}

std::optional<Vec3> convert(const toml::node& node, const Check& check, std::string& why, As<Vec3>) {
  const std::string expected = expected_text(check, As<Vec3>{});
  const auto* array = node.as_array();
  if (!array || array->size() != 3) {
    why = "expected " + expected + ", got " + describe(node);
    return std::nullopt;
  }
  const auto values = numbers_of(*array, check, expected, why);
  if (!values) return std::nullopt;
  return Vec3{(*values)[0], (*values)[1], (*values)[2]};
}

std::optional<std::vector<double>> convert(const toml::node& node, const Check& check,
                                           std::string& why, As<std::vector<double>>) {
  const std::string expected = expected_text(check, As<std::vector<double>>{});
  const auto* array = node.as_array();
  if (!array) {
    why = "expected " + expected + ", got " + describe(node);
    return std::nullopt;
  }
  return numbers_of(*array, check, expected, why);
}

}  // namespace talus::io
