#pragma once
// Below this many items a loop runs on one thread: waking a team costs more than it saves.
#include <cstddef>

namespace talus {
inline constexpr std::size_t kParallelThreshold = 2048;
inline bool worth_parallel(std::size_t items) { return items >= kParallelThreshold; }
}  // namespace talus
