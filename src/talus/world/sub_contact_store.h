#pragma once
// The contact points of a contact list's entries (rigid bodies with each other or with walls),
// stored by blocks of rows.
//
// A block's points lie in one buffer, in entry order, so the pass over a block reads last step's
// points as one stream and appends this step's to a second buffer, and the two trade places when
// the block is done. One small heap list per entry (the first layout) cost a cache miss on the
// list header and another on its points for every touching body pair: in a settled pile of
// crosses, with ~8 points per cross, those misses were a tenth of the step.
#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "talus/world/sub_contacts.h"

namespace talus {

class SubContactStore {
 public:
  static constexpr std::size_t kRowsPerBlock = 16;  ///< list rows per block (composite_pair_forces, wall_forces)

  // Lays out one list of points per entry of `list` (a PairList or a WallContactList);
  // `append(e, out)` appends entry e's points to `out`. The store's blocks then follow the
  // list's rows.
  template <class List, class Append>
  void assign(const List& list, Append&& append);
  template <class List>
  void assign(const List& list, const std::vector<SubContactList>& lists) {
    assign(list, [&](std::size_t e, std::vector<SubContact>& out) {
      out.insert(out.end(), lists[e].begin(), lists[e].end());
    });
  }
  // The store of `list`, new after a rebuild, from this one: entry e takes the points of old
  // entry origin[e] - 1, or of old entry -origin[e] - 1 seen from the other body, or none if
  // origin[e] is 0 (the `origin` of PairList::restore_memory, WallContactList::transfer_memory).
  template <class List>
  SubContactStore carried_to(const List& list, const std::vector<std::int64_t>& origin) const {
    return from_origin(list, origin, entries(), [this](std::size_t old) { return of(old); });
  }
  // The same from plain lists (carried between ranks or read from a checkpoint): origin[e]
  // names a list of `lists`, as above.
  template <class List>
  static SubContactStore from_lists(const List& list, const std::vector<std::int64_t>& origin,
                                    const std::vector<SubContactList>& lists) {
    return from_origin(list, origin, lists.size(),
                       [&lists](std::size_t k) { return std::span<const SubContact>(lists[k]); });
  }
  // Empty lists laid out on `list`, unless the store already follows its entries and rows.
  template <class List>
  void follow(const List& list) {
    if (entries() != list.entries() || blocks() != (list.rows() + kRowsPerBlock - 1) / kRowsPerBlock)
      assign(list, [](std::size_t, std::vector<SubContact>&) {});
  }
  void clear() { *this = SubContactStore{}; }

  std::size_t entries() const { return count_.size(); }
  std::size_t blocks() const { return blocks_.size(); }
  std::span<const SubContact> of(std::size_t e) const {
    if (count_[e] == 0) return {};  // first_ of a forgotten entry may point past its block's end
    return {blocks_[block_of_entry_[e]].current.data() + first_[e], count_[e]};
  }
  std::vector<SubContactList> lists() const;  ///< one list per entry (checkpoints)
  SubContactList list_of(std::size_t e) const {
    const std::span<const SubContact> points = of(e);
    return {points.begin(), points.end()};
  }

  // The pass over block b, entries in order: start_block(b), then for each entry either
  // take(e), whose points are appended to next_points(b) and recorded with record(e, first,
  // end), or forget(e); entries without points may be skipped. Last step's points are read
  // with a cursor, so the pass touches only the counts of the entries. Blocks are independent:
  // each may run on its own thread.
  void start_block(std::size_t b) {
    blocks_[b].next.clear();
    blocks_[b].cursor = 0;
  }
  std::vector<SubContact>& next_points(std::size_t b) { return blocks_[b].next; }
  std::span<const SubContact> take(std::size_t b, std::size_t e) {
    Block& block = blocks_[b];
    const std::span<const SubContact> points{block.current.data() + block.cursor, count_[e]};
    block.cursor += count_[e];
    return points;
  }
  void forget(std::size_t b, std::size_t e) {
    blocks_[b].cursor += count_[e];
    count_[e] = 0;
  }
  void record(std::size_t e, std::size_t first, std::size_t end) {
    first_[e] = static_cast<std::uint32_t>(first);
    count_[e] = static_cast<std::uint16_t>(end - first);
  }
  // Throws if an entry with points was skipped (its points would have been lost).
  void finish_block(std::size_t b);

 private:
  template <class List, class PointsOf>
  static SubContactStore from_origin(const List& list, const std::vector<std::int64_t>& origin, std::size_t sources,
                                     PointsOf&& points_of);

  struct Block {
    std::vector<SubContact> current, next;
    std::size_t cursor = 0;  ///< in current, during a pass
  };
  std::vector<Block> blocks_;
  std::vector<std::uint32_t> block_of_entry_;
  std::vector<std::uint32_t> first_;  ///< offset of the entry's points in its block's current buffer
  std::vector<std::uint16_t> count_;
};

template <class List, class Append>
void SubContactStore::assign(const List& list, Append&& append) {
  const std::size_t rows = list.rows();
  blocks_.assign((rows + kRowsPerBlock - 1) / kRowsPerBlock, Block{});
  block_of_entry_.assign(list.entries(), 0);
  first_.assign(list.entries(), 0);
  count_.assign(list.entries(), 0);
  for (std::size_t b = 0; b < blocks_.size(); ++b) {
    std::vector<SubContact>& out = blocks_[b].current;
    const std::size_t row_end = std::min(rows, (b + 1) * kRowsPerBlock);
    for (std::uint32_t e = list.row_begin(b * kRowsPerBlock); e < list.row_end(row_end - 1); ++e) {
      block_of_entry_[e] = static_cast<std::uint32_t>(b);
      const std::size_t first = out.size();
      append(e, out);
      record(e, first, out.size());
    }
  }
}

template <class List, class PointsOf>
SubContactStore SubContactStore::from_origin(const List& list, const std::vector<std::int64_t>& origin,
                                             std::size_t sources, PointsOf&& points_of) {
  SubContactStore fresh;
  fresh.assign(list, [&](std::size_t e, std::vector<SubContact>& out) {
    const std::int64_t o = origin[e];
    const std::size_t old = static_cast<std::size_t>(o > 0 ? o - 1 : -o - 1);
    if (o == 0 || old >= sources) return;
    const std::size_t first = out.size();
    const std::span<const SubContact> points = points_of(old);
    out.insert(out.end(), points.begin(), points.end());
    if (o < 0) reverse_points(std::span<SubContact>(out).subspan(first));
  });
  return fresh;
}

}  // namespace talus
