#include "talus/io/scenario_file.h"

#include <algorithm>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "talus/io/edit_distance.h"
#include "talus/io/input_file.h"
#include "talus/io/scenario_file_impl.h"
#include "talus/io/scenario_values.h"

namespace talus::io {

// ---- construction -------------------------------------------------------------------------

ScenarioFile::ScenarioFile(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
ScenarioFile::ScenarioFile(ScenarioFile&&) noexcept = default;
ScenarioFile& ScenarioFile::operator=(ScenarioFile&&) noexcept = default;
ScenarioFile::~ScenarioFile() = default;

ScenarioFile ScenarioFile::from_file(const std::filesystem::path& path) {
  return from_string(read_input_file(path), path.string(), path.parent_path());
}

ScenarioFile ScenarioFile::from_string(std::string_view text, std::string display_name,
                                       std::filesystem::path directory) {
  auto impl = std::make_unique<Impl>();
  impl->name = std::move(display_name);
  impl->directory = std::move(directory);
  try {
    impl->root = toml::parse(text, impl->name);
  } catch (const toml::parse_error& e) {
    const auto line = e.source().begin.line;
    const std::string location = line > 0 ? impl->name + ":" + std::to_string(line) : impl->name;
    throw InputError(location + ": " + std::string(e.description()));
  }
  return ScenarioFile(std::move(impl));
}

const std::string& ScenarioFile::display_name() const { return impl_->name; }

// ---- typed getters ------------------------------------------------------------------------

template <ScenarioValue T>
T ScenarioFile::get(std::string_view key, Check check) const {
  if constexpr (!NumericValue<T>) {
    if (check.kind != Check::Kind::None)
      throw std::invalid_argument("ScenarioFile: a range check on a non-numeric key '" +
                                  std::string(key) + "'");
  }
  const Impl::Found at = impl_->find(key);
  if (!at.node) impl_->raise(at, "missing required key (expected " + expected_text(check, As<T>{}) + ")");
  impl_->mark_used(at);
  std::string why;
  std::optional<T> value = convert(*at.node, check, why, As<T>{});
  if (!value) impl_->raise(at, why);
  return *std::move(value);
}

template <ScenarioValue T>
T ScenarioFile::get_or(std::string_view key, std::type_identity_t<T> fallback, Check check) const {
  if (!impl_->find(key).node) return fallback;
  return get<T>(key, check);
}

template double ScenarioFile::get<double>(std::string_view, Check) const;
template std::int64_t ScenarioFile::get<std::int64_t>(std::string_view, Check) const;
template int ScenarioFile::get<int>(std::string_view, Check) const;
template bool ScenarioFile::get<bool>(std::string_view, Check) const;
template std::string ScenarioFile::get<std::string>(std::string_view, Check) const;
template Vec3 ScenarioFile::get<Vec3>(std::string_view, Check) const;
template std::vector<double> ScenarioFile::get<std::vector<double>>(std::string_view, Check) const;
template double ScenarioFile::get_or<double>(std::string_view, double, Check) const;
template std::int64_t ScenarioFile::get_or<std::int64_t>(std::string_view, std::int64_t, Check) const;
template int ScenarioFile::get_or<int>(std::string_view, int, Check) const;
template bool ScenarioFile::get_or<bool>(std::string_view, bool, Check) const;
template std::string ScenarioFile::get_or<std::string>(std::string_view, std::string, Check) const;
template Vec3 ScenarioFile::get_or<Vec3>(std::string_view, Vec3, Check) const;
template std::vector<double> ScenarioFile::get_or<std::vector<double>>(std::string_view,
                                                                       std::vector<double>,
                                                                       Check) const;

std::filesystem::path ScenarioFile::get_path(std::string_view key) const {
  const std::string name = get<std::string>(key);
  const Impl::Found at = impl_->find(key);
  if (name.empty()) impl_->raise(at, "expected a file name, got an empty string");
  const std::filesystem::path path = (impl_->directory / name).lexically_normal();
  // In place, so that the value keeps its line for later messages. The node is the document's own.
  const_cast<toml::node*>(at.node)->as_string()->get() = std::filesystem::absolute(path).lexically_normal().string();
  return path;
}

std::string ScenarioFile::get_choice(std::string_view key,
                                     const std::vector<std::string>& allowed) const {
  std::string value = get<std::string>(key);
  if (std::find(allowed.begin(), allowed.end(), value) != allowed.end()) return value;
  std::string text = "must be one of ";
  for (std::size_t i = 0; i < allowed.size(); ++i) text += (i ? ", " : "") + quote_value(allowed[i]);
  text += ", got " + quote_value(value);
  if (auto guess = closest_match(value, allowed)) text += " (did you mean " + quote_value(*guess) + "?)";
  impl_->raise(impl_->find(key), text);
}

std::string ScenarioFile::get_choice_or(std::string_view key, std::string fallback,
                                        const std::vector<std::string>& allowed) const {
  if (!impl_->find(key).node) return fallback;
  return get_choice(key, allowed);
}

bool ScenarioFile::has(std::string_view key) const { return impl_->find(key).node != nullptr; }

// ---- structure ----------------------------------------------------------------------------

std::vector<std::string> ScenarioFile::table_keys(std::string_view key) const {
  const toml::table* table = &impl_->root;
  if (!key.empty()) {
    const Impl::Found at = impl_->find(key);
    if (!at.node) return {};
    impl_->mark_used(at);
    table = at.node->as_table();
    if (!table) impl_->raise(at, "expected a table, got " + describe(*at.node));
  }
  // File order, which a std::map-backed table forgets: sort by the key's source position.
  // Keys created by --set have no position (line 0) and so would sort first; put them last.
  std::vector<std::pair<const toml::key*, std::uint64_t>> keys;
  for (auto&& [k, v] : *table) {
    if (!is_key_name(k.str())) {
      KeyPath path = key.empty() ? KeyPath{} : parse_key_path(key);
      const std::string shown = (key.empty() ? "" : format_key_path(path) + ".") + quote_value(k.str());
      path.emplace_back(std::string(k.str()));
      throw InputError(Impl::compose(impl_->where(path, path.size(), &v), shown,
                                     "a name here must not be empty nor hold spaces, '.', '[', ']' or '='"));
    }
    const auto& pos = k.source().begin;
    const std::uint64_t order = pos.line == 0 ? std::numeric_limits<std::uint64_t>::max()
                                              : (std::uint64_t{pos.line} << 32) | pos.column;
    keys.emplace_back(&k, order);
  }
  std::stable_sort(keys.begin(), keys.end(),
                   [](const auto& a, const auto& b) { return a.second < b.second; });
  std::vector<std::string> names;
  for (const auto& [k, order] : keys) names.emplace_back(k->str());
  return names;
}

std::size_t ScenarioFile::array_size(std::string_view key) const {
  const Impl::Found at = impl_->find(key);
  if (!at.node) return 0;
  impl_->mark_used(at);
  const toml::array* array = at.node->as_array();
  if (!array) impl_->raise(at, "expected an array of tables, got " + describe(*at.node));
  return array->size();
}

void ScenarioFile::fail(std::string_view key, std::string_view message) const {
  impl_->raise(impl_->find(key), message);
}

// ---- output -------------------------------------------------------------------------------

std::string ScenarioFile::to_toml() const {
  std::ostringstream out;
  out << "# Scenario as run: " << impl_->name << "\n";
  for (const auto& text : impl_->override_texts) {
    std::string line = text;  // a line break would end the comment and corrupt the document
    std::replace(line.begin(), line.end(), '\n', ' ');
    out << "# --set " << line << "\n";
  }
  out << "\n" << toml::toml_formatter{impl_->root} << "\n";
  return std::move(out).str();
}

}  // namespace talus::io
