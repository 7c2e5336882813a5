#pragma once
// Below this many items a loop runs on one thread: waking a team costs more than it saves.
#include <cstddef>

namespace talus {
inline constexpr std::size_t kParallelThreshold = 2048;
inline bool worth_parallel(std::size_t items) { return items >= kParallelThreshold; }

// The same for the per-step passes over the periodic ghosts and their owners (refresh, fold,
// the steps of the late particles). A small chute has a third of its particles near a periodic
// face: run alone, these passes took a fifth of a 4,405-particle chute's step on two threads.
inline constexpr std::size_t kGhostParallelThreshold = 256;
inline bool worth_parallel_ghost_pass(std::size_t items) { return items >= kGhostParallelThreshold; }

// Tells the core that this thread waits on another (a spin on an atomic flag): yields the
// pipeline to a sibling hyperthread and saves power.
inline void spin_pause() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#endif
}
}  // namespace talus
