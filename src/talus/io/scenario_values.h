#pragma once
// Internal to ScenarioFile: turning one TOML node into a C++ value, and the words used for
// nodes and expectations in error messages. Kept apart so that the getters read as
// find / convert / report. Includes toml++, so only .cpp files of this folder include it.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "talus/io/toml_include.h"
#include "talus/io/value_check.h"
#include "talus/math/vec3.h"

namespace talus::io {

// Types a range Check applies to (each element of an array).
template <class T>
concept NumericValue = std::is_same_v<T, double> || std::is_same_v<T, std::int64_t> ||
                       std::is_same_v<T, int> || std::is_same_v<T, Vec3> ||
                       std::is_same_v<T, std::vector<double>>;

// Selects the overload for a target type.
template <class T>
struct As {};

// `"text"`, shortened to 40 characters, for quoting user values in messages.
std::string quote_value(std::string_view text);
// `-3`, `a string ("abc")`, `an array of 2 elements`, `a table`: what the user wrote.
std::string describe(const toml::node& node);

// What the getter wanted, e.g. "a positive number", "an array of 3 numbers in [0, 1]".
std::string expected_text(const Check& check, As<double>);
std::string expected_text(const Check& check, As<std::int64_t>);
std::string expected_text(const Check& check, As<int>);
std::string expected_text(const Check& check, As<bool>);
std::string expected_text(const Check& check, As<std::string>);
std::string expected_text(const Check& check, As<Vec3>);
std::string expected_text(const Check& check, As<std::vector<double>>);

// The value, or nothing with `why` set to the complaint ("expected a number, got ...",
// "must be positive, got -3").
std::optional<double> convert(const toml::node& node, const Check& check, std::string& why, As<double>);
std::optional<std::int64_t> convert(const toml::node& node, const Check& check, std::string& why,
                                    As<std::int64_t>);
std::optional<int> convert(const toml::node& node, const Check& check, std::string& why, As<int>);
std::optional<bool> convert(const toml::node& node, const Check& check, std::string& why, As<bool>);
std::optional<std::string> convert(const toml::node& node, const Check& check, std::string& why,
                                   As<std::string>);
std::optional<Vec3> convert(const toml::node& node, const Check& check, std::string& why, As<Vec3>);
std::optional<std::vector<double>> convert(const toml::node& node, const Check& check,
                                           std::string& why, As<std::vector<double>>);

}  // namespace talus::io
