#pragma once
// What a run spread over ranks needs beyond the engine (scenario/run_loop.cpp): the set-ups it
// refuses, and the scratch folder where ranks other than 0 write their copies of the outputs.
#include <filesystem>

#include "talus/scenario/scenario.h"

namespace talus {

// Throws, naming the scenario keys, if the run cannot be spread over ranks yet: particles
// poured during the run (insertion would need every rank's particles), particles removed
// when they leave the domain, rigid bodies of several convex parts.
void check_spreadable(const Scenario& sc);

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
