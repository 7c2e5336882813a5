#include "talus/scenario/spread_run.h"

#include <unistd.h>

#include <stdexcept>
#include <string>
#include <system_error>

namespace talus {

ScratchFolder::ScratchFolder(const std::filesystem::path& results, int rank) {
  path_ = std::filesystem::temp_directory_path() /
          ("talus-" + results.filename().string() + "-rank" + std::to_string(rank) + "-" + std::to_string(getpid()));
}

ScratchFolder::~ScratchFolder() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

}  // namespace talus
