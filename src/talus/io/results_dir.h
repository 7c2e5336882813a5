#pragma once
// The folder a run writes its results into.
#include <filesystem>
#include <string_view>

namespace talus::io {

// Creates `dir` and its parents. If `dir` already exists and is not empty, throws InputError
// unless `overwrite` is true, so a second run never mixes its files into an earlier run's
// results by accident; `allow_hint` is the option the user should pass to allow it. With
// `overwrite`, existing files are left in place and replaced one by one as the run writes them
// (nothing is deleted: a mistyped folder must never cost the user their data).
// Also throws InputError if `dir` exists but is not a directory, or cannot be created.
void prepare_results_dir(const std::filesystem::path& dir, bool overwrite,
                         std::string_view allow_hint = "--overwrite");

}  // namespace talus::io
