#include "talus/world/composite_stats.h"

#include <omp.h>

#include <array>

namespace talus {
namespace {

constexpr int kSlots = 64;
struct alignas(64) Slot {
  CompositeStats stats;
};
std::array<Slot, kSlots> g_slots;
bool g_enabled = false;

}  // namespace

CompositeStats& CompositeStats::operator+=(const CompositeStats& o) {
  body_pairs += o.body_pairs;
  part_pairs += o.part_pairs;
  narrow += o.narrow;
  points += o.points;
  box_full_queries += o.box_full_queries;
  box_reused += o.box_reused;
  box_refit += o.box_refit;
  box_recycled += o.box_recycled;
  box_apart_axis += o.box_apart_axis;
  box_touching += o.box_touching;
  cull_ticks += o.cull_ticks;
  narrow_ticks += o.narrow_ticks;
  force_ticks += o.force_ticks;
  total_ticks += o.total_ticks;
  return *this;
}

void set_composite_stats_enabled(bool on) { g_enabled = on; }
bool composite_stats_enabled() { return g_enabled; }
CompositeStats& composite_stats_slot() { return g_slots[omp_get_thread_num() % kSlots].stats; }

CompositeStats composite_stats_total() {
  CompositeStats t;
  for (const Slot& s : g_slots) t += s.stats;
  return t;
}

void reset_composite_stats() {
  for (Slot& s : g_slots) s.stats = {};
}

}  // namespace talus
