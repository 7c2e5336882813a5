#pragma once
// Counters and cycle totals of the contacts between rigid bodies, for the benchmark's
// profile: how many part pairs are tested, how many reach the narrow phase, and the time
// spent culling, in the narrow phase and in the force model. Off unless enabled: the timed
// runs pay one predictable branch per body pair.
#include <cstdint>

namespace talus {

struct CompositeStats {
  std::uint64_t body_pairs = 0;    ///< body pairs whose bounding spheres overlap
  std::uint64_t part_pairs = 0;    ///< part pairs tested (capsule cull)
  std::uint64_t narrow = 0;        ///< part pairs that reached the narrow phase
  std::uint64_t points = 0;        ///< contact points given to the force model
  std::uint64_t box_full_queries = 0;  ///< box part pairs (manifold mode) that ran the full SAT
  std::uint64_t box_reused = 0;        ///< ... served from their stored feature (box_pair_reuse.h)
  std::uint64_t box_refit = 0;         ///< ... of which refit from their stored points, without a clip
  std::uint64_t box_recycled = 0;      ///< ... of which recycled from their anchors (manifold_recycle)
  std::uint64_t box_apart_axis = 0;    ///< box part pairs kept apart by the axis that last separated them
  std::uint64_t box_touching = 0;      ///< box part pairs found touching (by any of the above)
  std::uint64_t cull_ticks = 0;    ///< time stamp counter ticks in part frames + capsule culls
  std::uint64_t narrow_ticks = 0;  ///< ... in the narrow phase (SAT, clipping, GJK)
  std::uint64_t force_ticks = 0;   ///< ... in the contact law and memory look-ups
  std::uint64_t total_ticks = 0;   ///< ... in the whole of composite_pair

  CompositeStats& operator+=(const CompositeStats& o);
};

void set_composite_stats_enabled(bool on);
bool composite_stats_enabled();
CompositeStats& composite_stats_slot();  ///< this OpenMP thread's counters
CompositeStats composite_stats_total();  ///< summed over threads
void reset_composite_stats();

}  // namespace talus
