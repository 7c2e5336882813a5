#pragma once
// Cost of the run loop's blow-up guard (world/state_guard.h: scan_state) on a cached chute
// state, against the steps it follows: the run loop scans once at the end of every batch of at
// most 64 steps (World::run), so each measurement times a batch of 64 steps and then the scan
// that follows it, with the particles' data as warm as the run loop finds it.
#include <filesystem>

#include "chute_state.h"

namespace talus::bench {

struct GuardCost {
  double step_seconds = 0;  ///< one time step (fastest batch / 64)
  double scan_seconds = 0;  ///< one scan of every owned particle (fastest)
};

GuardCost time_state_guard(const ChuteCase& c, const std::filesystem::path& cache_file, int threads, int repetitions);

}  // namespace talus::bench
