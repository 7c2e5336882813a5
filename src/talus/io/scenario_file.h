#pragma once
// A reader over a TOML scenario file that makes bad input impossible to miss.
//
// Every value is read through a typed getter addressed by a dotted key path
// ("contact.normal_stiffness", "species.glass.density", "walls[2].normal"). A value of the
// wrong type, out of range or missing is an InputError naming the file, line and key:
//     examples/impact.toml:12: contact.normal_stiffness: must be positive, got -3
// Every key the program reads is remembered, so that after setup check_no_unknown_keys()
// can report every key nobody read (a typo would otherwise silently fall back to a default):
//     examples/impact.toml:14: contact.normal_stifness: unknown key (did you mean contact.normal_stiffness?)
// Command-line overrides (`--set key=value`) replace or create keys; errors about them say
// `--set key: ...` instead of a file line.
//
// Not thread-safe: the bookkeeping of read keys is mutated by const getters.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "talus/io/input_error.h"
#include "talus/io/value_check.h"
#include "talus/math/vec3.h"

namespace talus::io {

// The value types a getter can return. An integer in the file is accepted where a double is
// expected; a float is accepted where an integer is expected only if it is a whole number in
// range (so `steps = 1e6` works).
template <class T>
concept ScenarioValue =
    std::is_same_v<T, double> || std::is_same_v<T, std::int64_t> || std::is_same_v<T, int> ||
    std::is_same_v<T, bool> || std::is_same_v<T, std::string> || std::is_same_v<T, Vec3> ||
    std::is_same_v<T, std::vector<double>>;

class ScenarioFile {
 public:
  // Throws InputError `PATH: cannot open: REASON` or, on a TOML syntax error, `PATH:LINE: message`.
  static ScenarioFile from_file(const std::filesystem::path& path);
  // Same, from text in memory; `display_name` stands for the file name in messages, and
  // `directory` for the file's folder, which relative paths in it start from (get_path).
  static ScenarioFile from_string(std::string_view text, std::string display_name,
                                  std::filesystem::path directory = {});

  ScenarioFile(ScenarioFile&&) noexcept;
  ScenarioFile& operator=(ScenarioFile&&) noexcept;
  ~ScenarioFile();

  const std::string& display_name() const;

  // Applies one `--set KEY=VALUE`. VALUE is parsed as a TOML value (number, bool, string,
  // array, inline table); text that is not valid TOML is taken as a plain string, so
  // `--set contact.model=hertz` works without quotes. Replaces the key or creates it (and
  // missing parent tables). Throws InputError `--set KEY: ...` if the text has no '=', the
  // key is malformed, or a parent on the path is not a table (or an index is out of range).
  void set_override(std::string_view assignment);

  // Required value: throws InputError if missing, of the wrong type, or failing `check`.
  // `check` applies to numbers, and to every element of a Vec3 or array of doubles.
  template <ScenarioValue T>
  T get(std::string_view key, Check check = {}) const;

  // Optional value: `fallback` if the key is absent (the fallback is not checked); a present
  // value is checked exactly as in get(). T is never deduced, so get_or<double>("dt", 1)
  // cannot silently become an integer getter.
  template <ScenarioValue T>
  T get_or(std::string_view key, std::type_identity_t<T> fallback, Check check = {}) const;

  // A file named by a string: a relative path starts from the scenario file's folder (the
  // current one for text without a directory), so a scenario and its files move together. The
  // path comes back as the folder joined with the name, for messages; the document keeps it
  // made absolute, so the copy to_toml() leaves in a results folder or a checkpoint names the
  // same file from wherever it is read.
  std::filesystem::path get_path(std::string_view key) const;

  // A string that must be one of `allowed` (e.g. a model name); the error lists them and
  // suggests the closest.
  std::string get_choice(std::string_view key, const std::vector<std::string>& allowed) const;
  std::string get_choice_or(std::string_view key, std::string fallback,
                            const std::vector<std::string>& allowed) const;

  // Whether the key is present. Does not mark it read.
  bool has(std::string_view key) const;

  // Names of the keys of a table, in file order (keys created by --set come last); empty if
  // the table is absent. "" is the top level. Marks the table itself read, not its keys.
  // Callers build key paths from the names, so a name no path can hold (empty, or with a
  // space, '.', '[', ']' or '=': `[species."glass beads"]`) is an InputError at its line.
  std::vector<std::string> table_keys(std::string_view key) const;
  // Number of entries of an array (of tables); 0 if absent. Marks the array itself read.
  std::size_t array_size(std::string_view key) const;

  // Throws InputError `FILE:LINE: KEY: message` for checks the reader cannot express
  // (e.g. "must be smaller than the box"). If the key is absent, the line of its nearest
  // present parent is used.
  [[noreturn]] void fail(std::string_view key, std::string_view message) const;

  // Throws one InputError listing every key that was never read, one line each, in file
  // order (overrides last), with a "did you mean" suggestion among the keys the program
  // asked for. Call it once all setup code has read its keys.
  void check_no_unknown_keys() const;
  // If `key` is never read, check_no_unknown_keys reports it as `not read: why` rather than as
  // unknown: a key the reader knows but the chosen models have no use for.
  void explain_if_unread(std::string_view key, std::string why) const;

  // The final document (overrides applied) as TOML, headed by comments naming the source
  // file and the overrides, for copying into the results folder. Numbers keep full precision,
  // so reading it back reproduces the run; comments and layout of the original are not kept.
  std::string to_toml() const;

 private:
  struct Impl;
  explicit ScenarioFile(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace talus::io
