#include "talus/io/results_dir.h"

#include <string>

#include "talus/io/input_error.h"

namespace talus::io {

void prepare_results_dir(const std::filesystem::path& dir, bool overwrite,
                         std::string_view allow_hint) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(dir, ec);
  if (fs::exists(status)) {
    if (!fs::is_directory(status))
      throw InputError(dir.string() + ": output folder exists and is not a directory");
    const bool empty = fs::is_empty(dir, ec);
    if (ec) throw InputError(dir.string() + ": cannot read output folder: " + ec.message());
    if (!empty && !overwrite)
      throw InputError(dir.string() + ": output folder exists and is not empty; choose another " +
                       "folder, or pass " + std::string(allow_hint) +
                       " to write into it (files of the same name are replaced)");
    return;
  }
  fs::create_directories(dir, ec);
  if (ec) throw InputError(dir.string() + ": cannot create output folder: " + ec.message());
}

}  // namespace talus::io
