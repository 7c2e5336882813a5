#pragma once
// How many steps the next batch of a run holds (World::run closes one step and opens the next
// in one pass over memory, so steps run in batches): up to and including the first step whose
// end reaches the time something is due, and at most kMaxBatchSteps, so that the blow-up guard,
// progress and stop requests (Ctrl-C) stay prompt. Shared by the run loop (run_loop.h) and the
// stepped run of the Python module (stepped_run.h), so that both cut their batches alike.
#include <cstdint>

namespace talus {

inline constexpr std::uint64_t kMaxBatchSteps = 64;

// `now` s, the world's time; `dt` s, its step; `due` s. At least one step.
inline std::uint64_t steps_until(double now, double dt, double due) {
  std::uint64_t steps = 0;
  for (double t = now; steps < kMaxBatchSteps;) {
    t += dt;  // as World::step advances its clock
    ++steps;
    if (t >= due) break;
  }
  return steps;
}

}  // namespace talus
