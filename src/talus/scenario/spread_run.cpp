#include "talus/scenario/spread_run.h"

#include <unistd.h>

#include <stdexcept>
#include <string>
#include <system_error>

namespace talus {

void check_spreadable(const Scenario& sc) {
  const auto refuse = [](const std::string& what) {
    throw std::runtime_error(what + " runs on one rank only (for now): start it without mpirun");
  };
  if (!sc.pours.empty()) refuse("a scenario with [[pour]] (particles inserted while it runs)");
  if (sc.control.on_leave == LeavePolicy::remove) refuse("a scenario with domain.on_leave = \"delete\"");
}

ScratchFolder::ScratchFolder(const std::filesystem::path& results, int rank) {
  path_ = std::filesystem::temp_directory_path() /
          ("talus-" + results.filename().string() + "-rank" + std::to_string(rank) + "-" + std::to_string(getpid()));
}

ScratchFolder::~ScratchFolder() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

}  // namespace talus
