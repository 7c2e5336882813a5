#pragma once
// What a run spread over ranks needs beyond the engine (scenario/run_loop.cpp): the scratch
// folder where ranks other than 0 write their copies of the outputs.
#include <filesystem>

#include "talus/scenario/scenario.h"

namespace talus {


// A private folder for one rank's outputs, removed with everything in it when this goes.
class ScratchFolder {
 public:
  ScratchFolder(const std::filesystem::path& results, int rank);
  ~ScratchFolder();
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace talus
