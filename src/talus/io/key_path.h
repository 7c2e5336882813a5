#pragma once
// Dotted key paths that address a value in a scenario file: "contact.normal_stiffness",
// "species.glass.density", "walls[2].normal" (0-based index into an array of tables).
// Key names may hold any character except '.', '[', ']', '=' and spaces; quoted TOML keys
// with such characters cannot be addressed (Talus scenario files never need them).
#include <cstddef>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace talus::io {

// One step of a path: a table key or an array index.
using PathStep = std::variant<std::string, std::size_t>;
using KeyPath = std::vector<PathStep>;

// Throws std::invalid_argument with a short reason ("empty key name", "bad index") on bad syntax.
KeyPath parse_key_path(std::string_view text);

// Whether `name` can be one step of a path: not empty, none of the characters above.
bool is_key_name(std::string_view name);

// The canonical text of the first `count` steps of a path ("walls[2].normal").
std::string format_key_path(const KeyPath& path, std::size_t count);
inline std::string format_key_path(const KeyPath& path) { return format_key_path(path, path.size()); }

}  // namespace talus::io
