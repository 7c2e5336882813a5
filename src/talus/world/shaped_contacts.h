#pragma once
// The contacts of rigid bodies made of convex parts (crosses) in a World: the contact points of
// every list entry, the parts placed this step, the per-part-pair budgets that skip pairs known
// apart, and the scratch in which the force pass bins its loads (composite_forces.cpp).
#include <array>
#include <cstdint>
#include <vector>

#include "talus/math/vec3.h"
#include "talus/world/block_schedule.h"
#include "talus/world/pair_budgets.h"
#include "talus/world/placed_bodies.h"
#include "talus/world/sub_contact_store.h"

namespace talus {

struct ShapedContacts {
  SubContactStore pair_points, wall_points;  ///< per particle-pair and particle-wall entry
  PlacedBodies placed;  ///< parts of the rigid bodies in the world, this step
  // Per list entry and per part pair: found apart, and so while the two bodies' travels
  // (PlacedBodies::travel) add up to less than the budget. Cleared at every rebuild.
  PairBudgets budgets;
  // Contributions to forces and torques per block of rows, binned by the receiving body's range
  // of indices, applied after the pass range by range (in parallel) and block by block within
  // a range.
  struct BodyLoad {
    std::uint32_t body;
    Vec3 force, torque;
  };
  static constexpr int kLoadRanges = 8;
  using BlockLoads = std::array<std::vector<BodyLoad>, kLoadRanges>;
  std::vector<BlockLoads> block_loads;
  BlockSchedule block_schedule;
  // Per block of rows, what the last pass found: the entries then awake (in row order) and,
  // per row, a wake-up bound on the entries then asleep, on the scale of the row's own travel
  // plus PlacedBodies::travel_clock. While a row stays below it, none of those entries can have
  // woken, so the pass tests the awake ones alone instead of all the row's neighbours (some 37
  // for a cross in a pile, one in ten awake): the same entries, in the same order.
  static constexpr std::size_t kRowsPerBlock = SubContactStore::kRowsPerBlock;
  struct BlockWake {
    std::vector<std::uint32_t> awake;
    std::array<std::uint32_t, kRowsPerBlock + 1> start{};
    std::array<double, kRowsPerBlock> asleep_until{};
    bool valid = false;
  };
  std::vector<BlockWake> block_wake;  ///< cleared with the budgets
};

}  // namespace talus
