#pragma once
// The whole of a file the user named (a scenario, a mesh), as bytes.
#include <filesystem>
#include <string>

namespace talus::io {

// Throws InputError `PATH: cannot open: REASON` (a directory included) or `PATH: cannot read: REASON`.
std::string read_input_file(const std::filesystem::path& path);

}  // namespace talus::io
