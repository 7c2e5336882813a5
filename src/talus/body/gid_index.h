#pragma once
// A map from global particle ids to local indices (rows, groups, flags), sized by the particles
// a rank holds, not by the ids of the whole system: an array indexed by global id costs every
// rank 4 bytes per particle of the run, which at 10^8 particles is 400 MB a rank whatever the
// rank count. Open addressing with linear probing over a power-of-two table at most half full;
// Fibonacci hashing spreads the ids, which arrive in runs.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace talus {

class GidIndex {
 public:
  static constexpr std::int32_t kAbsent = -1;

  // Empties the map and makes room for n ids without growing; the table's memory is kept, so
  // that a map refilled at every rebuild does not map its pages again.
  void reset(std::size_t n) {
    std::size_t capacity = 16;
    while (capacity < 2 * n) capacity *= 2;
    if (capacity > slots_.size()) {
      slots_.assign(capacity, Slot{});
    } else {
      capacity = slots_.size();
      for (Slot& s : slots_) s = Slot{};
    }
    shift_ = 64;
    for (std::size_t c = capacity; c > 1; c /= 2) --shift_;
    size_ = 0;
  }

  // The map from each id of `gids` to its position in it.
  void index_positions(std::span<const std::uint32_t> gids) {
    reset(gids.size());
    for (std::size_t i = 0; i < gids.size(); ++i) put(gids[i], static_cast<std::int32_t>(i));
  }

  // Sets the value of `gid`, adding it if absent (growing the table past half full).
  void put(std::uint32_t gid, std::int32_t value) {
    if (2 * (size_ + 1) > slots_.size()) grow();
    Slot& s = slots_[probe(gid)];
    if (s.gid == kEmpty) {
      s.gid = gid;
      ++size_;
    }
    s.value = value;
  }

  // The value of `gid`, or kAbsent.
  std::int32_t find(std::uint32_t gid) const {
    if (slots_.empty()) return kAbsent;
    return slots_[probe(gid)].value;
  }

  std::size_t size() const { return size_; }
  std::size_t bytes() const { return slots_.capacity() * sizeof(Slot); }

 private:
  static constexpr std::uint32_t kEmpty = 0xffffffffu;  // no particle gets this id (World::add)
  struct Slot {
    std::uint32_t gid = kEmpty;
    std::int32_t value = kAbsent;
  };

  std::size_t probe(std::uint32_t gid) const {  // the slot of gid, or the empty one it would take
    const std::size_t mask = slots_.size() - 1;
    std::size_t at = static_cast<std::size_t>((std::uint64_t{gid} * 0x9e3779b97f4a7c15ull) >> shift_);
    while (slots_[at].gid != gid && slots_[at].gid != kEmpty) at = (at + 1) & mask;
    return at;
  }

  void grow() {
    const std::vector<Slot> old = std::move(slots_);
    slots_.clear();
    reset(old.empty() ? 8 : old.size());
    for (const Slot& s : old)
      if (s.gid != kEmpty) put(s.gid, s.value);
  }

  std::vector<Slot> slots_;
  int shift_ = 64;
  std::size_t size_ = 0;
};

}  // namespace talus
