#pragma once
// Internal to ScenarioFile (its .cpp files only): the parsed document plus the bookkeeping
// that turns silent mistakes into errors - which keys were read, which were asked for, and
// which came from --set - and the one place that decides how a key's location is written.
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "talus/io/key_path.h"
#include "talus/io/scenario_file.h"
#include "talus/io/toml_include.h"

namespace talus::io {

struct ScenarioFile::Impl {
  std::string name;  ///< file name as given by the user, used in every message
  std::filesystem::path directory;  ///< the file's folder, where relative paths in it start
  toml::table root;
  // Canonical keys the program read, with all their parents ("walls", "walls[2]", ...).
  mutable std::set<std::string, std::less<>> used;
  // Every key the program asked for, present or not: the candidates for "did you mean".
  mutable std::set<std::string, std::less<>> requested;
  // Keys that exist in the scenario's vocabulary but that the chosen models do not read, with
  // why: reported as such instead of as unknown keys (explain_if_unread).
  mutable std::map<std::string, std::string, std::less<>> unread_reasons;
  // Keys set by --set, so their errors point at the command line instead of the file.
  std::set<std::string, std::less<>> overridden;
  std::vector<std::string> override_texts;  ///< as typed, in order, for to_toml()

  // Where a key path leads: the value if present, else the deepest present parent.
  struct Found {
    KeyPath path;
    std::string key;                      ///< canonical text of the path
    const toml::node* node = nullptr;     ///< the value, null if absent
    const toml::node* nearest = nullptr;  ///< the value, or its deepest present parent
    std::size_t depth = 0;                ///< path steps covered by `nearest`
  };

  // Records the key as asked for. Throws InputError if the path runs through a value that
  // is not a table (or array), std::invalid_argument if the key text is malformed (a bug).
  Found find(std::string_view key_text) const;
  // Marks the key and all its parents read.
  void mark_used(const Found& at) const;

  // "--set KEY" if the first `depth` steps of the path lie inside an override, else
  // "FILE:LINE" from the node's source, else just "FILE".
  std::string where(const KeyPath& path, std::size_t depth, const toml::node* node) const;
  // "LOCATION: KEY: text", without repeating KEY when LOCATION is "--set KEY".
  static std::string compose(const std::string& location, const std::string& key,
                             std::string_view text);
  [[noreturn]] void raise(const Found& at, std::string_view text) const;
  [[noreturn]] void raise_at(const KeyPath& path, std::size_t depth, const toml::node* node,
                             std::string_view text) const;

  // Leaves nobody read (and empty tables nobody listed) under `node`, with their paths.
  void collect_unread(const toml::node& node, KeyPath& path,
                      std::vector<std::pair<KeyPath, const toml::node*>>& out) const;
};

}  // namespace talus::io
