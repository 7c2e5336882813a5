// ScenarioFile::set_override: `--set KEY=VALUE` from the command line.
#include <stdexcept>

#include "talus/io/scenario_file_impl.h"
#include "talus/io/scenario_values.h"

namespace talus::io {

namespace {

std::string trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t");
  return std::string(s.substr(first, last - first + 1));
}

}  // namespace

void ScenarioFile::set_override(std::string_view assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string_view::npos)
    throw InputError("--set " + std::string(assignment) + ": expected KEY=VALUE");
  const std::string key_text = trim(assignment.substr(0, eq));
  const std::string value_text = trim(assignment.substr(eq + 1));
  KeyPath path;
  try {
    path = parse_key_path(key_text);
  } catch (const std::invalid_argument& e) {
    throw InputError("--set " + key_text + ": malformed key (" + e.what() + ")");
  }
  const std::string key = format_key_path(path);
  const auto fail = [&](const std::string& text) -> void {
    throw InputError("--set " + key + ": " + text);
  };

  // Parse the value as the right-hand side of a TOML assignment; anything that is not valid
  // TOML (a bare word like `hertz`) is taken as the string it looks like.
  toml::table parsed;
  try {
    const std::string document = "v = " + value_text + "\n";
    parsed = toml::parse(std::string_view(document), std::string_view("--set"));
  } catch (const toml::parse_error&) {
  }
  const bool is_toml = parsed.size() == 1 && parsed.contains("v");
  const auto assign_table = [&](toml::table& table, const std::string& name) {
    if (is_toml)
      table.insert_or_assign(name, parsed["v"]);
    else
      table.insert_or_assign(name, value_text);
  };

  toml::node* cur = &impl_->root;
  for (std::size_t k = 0; k < path.size(); ++k) {
    const bool last = k + 1 == path.size();
    const std::string prefix = format_key_path(path, k + 1);
    if (const auto* name = std::get_if<std::string>(&path[k])) {
      toml::table* table = cur->as_table();
      if (!table) fail(format_key_path(path, k) + " is " + describe(*cur) + ", not a table");
      if (last) {
        assign_table(*table, *name);
        break;
      }
      toml::node* child = table->get(*name);
      if (!child) {
        if (std::holds_alternative<std::size_t>(path[k + 1]))
          fail(prefix + " does not exist, so it cannot be indexed");
        child = &table->insert(*name, toml::table{}).first->second;
      }
      cur = child;
    } else {
      const std::size_t index = std::get<std::size_t>(path[k]);
      toml::array* array = cur->as_array();
      if (!array) fail(format_key_path(path, k) + " is " + describe(*cur) + ", not an array");
      if (index >= array->size())
        fail(format_key_path(path, k) + " has only " + std::to_string(array->size()) +
             (array->size() == 1 ? " entry" : " entries"));
      if (last) {
        if (is_toml)
          array->replace(array->cbegin() + static_cast<std::ptrdiff_t>(index), parsed["v"]);
        else
          array->replace(array->cbegin() + static_cast<std::ptrdiff_t>(index), value_text);
        break;
      }
      cur = array->get(index);
    }
  }

  // A later override of a parent replaces whatever earlier overrides set below it.
  std::erase_if(impl_->overridden, [&](const std::string& k) {
    return k.size() > key.size() && k.starts_with(key) && (k[key.size()] == '.' || k[key.size()] == '[');
  });
  impl_->overridden.insert(key);
  impl_->override_texts.push_back(key + "=" + value_text);
}

}  // namespace talus::io
