#include "talus/world/block_schedule.h"

#include <algorithm>

namespace talus {

void BlockSchedule::plan(long blocks, int threads) {
  const auto n = static_cast<std::size_t>(blocks);
  if (cost_.size() != n) cost_.assign(n, 1);
  if (ranges_.size() != static_cast<std::size_t>(threads)) ranges_ = std::vector<Range>(static_cast<std::size_t>(threads));
  std::uint64_t total = 0;
  for (std::uint64_t c : cost_) total += std::max<std::uint64_t>(c, 1);
  // Thread t starts where the running cost passes t / threads of the total.
  std::uint64_t running = 0;
  std::size_t block = 0;
  for (int t = 0; t < threads; ++t) {
    const std::size_t front = block;
    const std::uint64_t goal = total / static_cast<std::uint64_t>(threads) * static_cast<std::uint64_t>(t + 1);
    if (t == threads - 1)
      block = n;
    else
      while (block < n && running + std::max<std::uint64_t>(cost_[block], 1) / 2 < goal)
        running += std::max<std::uint64_t>(cost_[block++], 1);
    ranges_[static_cast<std::size_t>(t)].bounds.store(
        pack(static_cast<std::uint32_t>(front), static_cast<std::uint32_t>(block)), std::memory_order_relaxed);
  }
}

bool BlockSchedule::take_front(Range& r, long& block) {
  std::uint64_t b = r.bounds.load(std::memory_order_relaxed);
  for (;;) {
    const auto front = static_cast<std::uint32_t>(b >> 32), back = static_cast<std::uint32_t>(b);
    if (front >= back) return false;
    if (r.bounds.compare_exchange_weak(b, pack(front + 1, back), std::memory_order_relaxed)) {
      block = front;
      return true;
    }
  }
}

bool BlockSchedule::take_back(Range& r, long& block) {
  std::uint64_t b = r.bounds.load(std::memory_order_relaxed);
  for (;;) {
    const auto front = static_cast<std::uint32_t>(b >> 32), back = static_cast<std::uint32_t>(b);
    if (front >= back) return false;
    if (r.bounds.compare_exchange_weak(b, pack(front, back - 1), std::memory_order_relaxed)) {
      block = back - 1;
      return true;
    }
  }
}

bool BlockSchedule::next(int thread, long& block) {
  const auto threads = static_cast<int>(ranges_.size());
  if (take_front(ranges_[static_cast<std::size_t>(thread)], block)) return true;
  for (int k = 1; k < threads; ++k)
    if (take_back(ranges_[static_cast<std::size_t>((thread + k) % threads)], block)) return true;
  return false;
}

}  // namespace talus
