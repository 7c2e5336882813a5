#pragma once
// Sleep budgets of the pair list's entries (conservative advancement, PlacedBodies::travel):
// a pair found apart by a gap g when the two bodies' travels summed to T cannot touch while
// their travels sum to less than T + g, so it is not tested again until then.
//
// Each entry has one budget for its two bodies and one per pair of their convex parts: a body
// pair in contact (two crosses touching by one arm) then still skips its part pairs that were
// found apart, instead of running their capsule test and box SAT every step. Its touching box
// pairs keep their SAT axis the same way (AxisBudget).
#include <cstdint>
#include <vector>

#include "talus/body/particles.h"
#include "talus/collide/pair_list.h"
#include "talus/shape/composite_shape.h"

namespace talus {

// A touching box pair's SAT axis, sure to stay the SAT's answer while the two bodies' travels
// sum to less than `until` (box_box_axis_reserve).
struct AxisBudget {
  double until = 0;  ///< m, on the scale of PlacedBodies::travel
  int axis = -1;
};

class PairBudgets {
 public:
  // True while the budgets belong to the current list (cleared at every rebuild).
  bool matches(const PairList& list) const { return body_.size() == list.entries(); }
  // Zero budgets (every pair is tested) for each entry of `list` and each pair of its bodies' parts.
  void reset(const PairList& list, const ParticleStore& p, const std::vector<CompositeShape>& shapes);
  void clear() { body_.clear(); }
  double* body() { return body_.data(); }
  // Entry e's part-pair budgets, row-major: part a of i with part b of j at a * parts(j) + b.
  double* parts(std::size_t e) { return part_.data() + part_begin_[e]; }
  // Entry e's part-pair axis budgets, laid out as parts(e).
  AxisBudget* axes(std::size_t e) { return axis_.data() + part_begin_[e]; }

 private:
  std::vector<double> body_;
  std::vector<std::uint32_t> part_begin_;
  std::vector<double> part_;
  std::vector<AxisBudget> axis_;
};

}  // namespace talus
