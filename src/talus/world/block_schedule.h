#pragma once
// Which thread computes which block of neighbour-list rows in the rigid-body force loop.
//
// Each thread owns a contiguous range of blocks, cut where last step's measured cost splits the
// loop evenly, and walks it from the front; a thread done early takes blocks from the back of
// the others' ranges. A thread so keeps, step after step, the same rows and with them their
// contact lists, budgets and placed parts in its own core's cache; first come, first served
// (OpenMP's dynamic schedule) moved them between the two cores every step. Which thread
// computes a block never changes the result: each block records its loads apart.
#include <atomic>
#include <cstdint>
#include <vector>

namespace talus {

class BlockSchedule {
 public:
  BlockSchedule() = default;
  // A copy keeps the costs; its ranges are planned afresh.
  BlockSchedule(const BlockSchedule& o) : cost_(o.cost_) {}
  BlockSchedule& operator=(const BlockSchedule& o) {
    cost_ = o.cost_;
    ranges_.clear();
    return *this;
  }
  // Splits [0, blocks) among `threads` by the costs recorded last time (evenly by count when
  // the number of blocks changed). Call before the threads start.
  void plan(long blocks, int threads);
  // The next block for `thread`: its own range first, then the others' tails. False when none
  // is left.
  bool next(int thread, long& block);
  // What block `block` cost this time (any unit, e.g. ticks).
  void record(long block, std::uint64_t cost) { cost_[static_cast<std::size_t>(block)] = cost; }

 private:
  // [front, back) of one thread's range in one word, so owner and thief agree by one CAS.
  struct alignas(64) Range {
    std::atomic<std::uint64_t> bounds{0};
  };
  static std::uint64_t pack(std::uint32_t front, std::uint32_t back) { return std::uint64_t{front} << 32 | back; }
  bool take_front(Range& r, long& block);
  bool take_back(Range& r, long& block);

  std::vector<std::uint64_t> cost_;
  std::vector<Range> ranges_;
};

}  // namespace talus
