#include "talus/io/scenario_file_impl.h"

#include <stdexcept>

#include "talus/io/scenario_values.h"

namespace talus::io {

ScenarioFile::Impl::Found ScenarioFile::Impl::find(std::string_view key_text) const {
  Found at;
  try {
    at.path = parse_key_path(key_text);
  } catch (const std::invalid_argument& e) {
    // A malformed key in a getter call is a bug in Talus, not in the user's file.
    throw std::invalid_argument("ScenarioFile: bad key path '" + std::string(key_text) +
                                "': " + e.what());
  }
  at.key = format_key_path(at.path);
  requested.insert(at.key);
  const toml::node* cur = &root;
  for (std::size_t k = 0; k < at.path.size(); ++k) {
    const toml::node* next = nullptr;
    if (const auto* name_step = std::get_if<std::string>(&at.path[k])) {
      const toml::table* table = cur->as_table();
      if (!table) raise_at(at.path, k, cur, "expected a table, got " + describe(*cur));
      next = table->get(*name_step);
    } else {
      const toml::array* array = cur->as_array();
      if (!array) raise_at(at.path, k, cur, "expected an array of tables, got " + describe(*cur));
      next = array->get(std::get<std::size_t>(at.path[k]));
    }
    if (!next) {
      at.nearest = cur;
      at.depth = k;
      return at;
    }
    cur = next;
  }
  at.node = at.nearest = cur;
  at.depth = at.path.size();
  return at;
}

void ScenarioFile::Impl::mark_used(const Found& at) const {
  for (std::size_t k = 1; k <= at.path.size(); ++k) used.insert(format_key_path(at.path, k));
}

std::string ScenarioFile::Impl::where(const KeyPath& path, std::size_t depth,
                                      const toml::node* node) const {
  for (std::size_t k = depth; k >= 1; --k) {
    const std::string prefix = format_key_path(path, k);
    if (overridden.contains(prefix)) return "--set " + prefix;
  }
  if (node && node != &root && node->source().begin.line > 0)
    return name + ":" + std::to_string(node->source().begin.line);
  return name;
}

std::string ScenarioFile::Impl::compose(const std::string& location, const std::string& key,
                                        std::string_view text) {
  if (location == "--set " + key) return location + ": " + std::string(text);
  return location + ": " + key + ": " + std::string(text);
}

void ScenarioFile::Impl::raise(const Found& at, std::string_view text) const {
  throw InputError(compose(where(at.path, at.depth, at.nearest), at.key, text));
}

void ScenarioFile::Impl::raise_at(const KeyPath& path, std::size_t depth, const toml::node* node,
                                  std::string_view text) const {
  throw InputError(compose(where(path, depth, node), format_key_path(path, depth), text));
}

}  // namespace talus::io
