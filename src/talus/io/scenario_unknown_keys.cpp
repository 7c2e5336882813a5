// ScenarioFile::check_no_unknown_keys: every key in the file must have been read by someone.
#include <algorithm>
#include <tuple>

#include "talus/io/edit_distance.h"
#include "talus/io/scenario_file_impl.h"

namespace talus::io {

void ScenarioFile::Impl::collect_unread(
    const toml::node& node, KeyPath& path,
    std::vector<std::pair<KeyPath, const toml::node*>>& out) const {
  const std::string key = format_key_path(path);
  if (const toml::table* table = node.as_table()) {
    if (table->empty() && !path.empty() && !used.contains(key)) out.emplace_back(path, &node);
    for (auto&& [k, child] : *table) {
      path.emplace_back(std::string(k.str()));
      collect_unread(child, path, out);
      path.pop_back();
    }
    return;
  }
  if (const toml::array* array = node.as_array(); array && array->is_array_of_tables()) {
    for (std::size_t i = 0; i < array->size(); ++i) {
      path.emplace_back(i);
      collect_unread(*array->get(i), path, out);
      path.pop_back();
    }
    return;
  }
  if (!used.contains(key)) out.emplace_back(path, &node);
}

void ScenarioFile::check_no_unknown_keys() const {
  std::vector<std::pair<KeyPath, const toml::node*>> unread;
  KeyPath path;
  impl_->collect_unread(impl_->root, path, unread);
  if (unread.empty()) return;

  struct Report {
    bool from_override;
    std::uint32_t line;
    std::string text;
  };
  const std::vector<std::string> candidates(impl_->requested.begin(), impl_->requested.end());
  std::vector<Report> reports;
  for (const auto& [key_path, node] : unread) {
    const std::string key = format_key_path(key_path);
    const std::string location = impl_->where(key_path, key_path.size(), node);
    std::string text = "unknown key";
    if (auto reason = impl_->unread_reasons.find(key); reason != impl_->unread_reasons.end())
      text = "not read: " + reason->second;
    else if (auto guess = closest_match(key, candidates))
      text += " (did you mean " + *guess + "?)";
    reports.push_back({location.starts_with("--set "), node->source().begin.line,
                       Impl::compose(location, key, text)});
  }
  std::stable_sort(reports.begin(), reports.end(), [](const Report& a, const Report& b) {
    return std::tie(a.from_override, a.line) < std::tie(b.from_override, b.line);
  });
  std::vector<std::string> lines;
  for (auto& r : reports) lines.push_back(std::move(r.text));
  throw InputError(std::move(lines));
}

void ScenarioFile::explain_if_unread(std::string_view key, std::string why) const {
  impl_->unread_reasons.insert_or_assign(std::string(key), std::move(why));
}

}  // namespace talus::io
