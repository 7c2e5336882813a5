#pragma once
// Sleep budgets of the pair list's entries (conservative advancement, PlacedBodies::travel):
// a pair found apart by a gap g when the two bodies' travels summed to T cannot touch while
// their travels sum to less than T + g, so it is not tested again until then.
//
// Each entry has one budget for its two bodies and one per pair of their convex parts: a body
// pair in contact (two crosses touching by one arm) then still skips its part pairs that were
// found apart, instead of running their capsule test and box SAT every step. Its touching box
// pairs keep their SAT axis the same way (PartBudget::axis).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "talus/body/particles.h"
#include "talus/collide/pair_list.h"
#include "talus/shape/composite_shape.h"

namespace talus {

// A pair of convex parts is either apart or touching, so one bound serves both budgets: with
// axis < 0 the pair sleeps while the two bodies' travels sum to less than `until`; with axis >= 0
// the parts touched and, being boxes, their SAT axis stays the SAT's answer until then
// (box_box_axis_reserve). Boxes found apart by the SAT keep the axis that separated them, as
// axis = -2 - k: when they wake, that one axis usually still separates them, and the 15-axis
// search is skipped (near pairs of crossing arms are mostly apart along an edge axis, the
// search's last). One 16-byte record per part pair: a cross pair's four share a line.
// A touching pair's stored points may also be refit from their features, without the clip
// (box_pair_reuse.h), while the travels sum to less than until - refit_slack: a float in the
// record's padding, rounded up, so the bound errs towards clipping again.
struct PartBudget {
  double until = 0;  ///< m, on the scale of PlacedBodies::travel
  std::int32_t axis = -1;
  float refit_slack = std::numeric_limits<float>::infinity();  ///< m; infinite: no refit

  bool asleep(double travelled) const { return axis < 0 && travelled < until; }
  // Apart by at least `gap`; `separating_axis` (0-14) is the box SAT axis that showed it, if any.
  void sleep(double travelled, double gap, int separating_axis = -1) {
    axis = -2 - separating_axis;
    until = travelled + gap;
  }
  int separating_axis() const { return axis <= -2 ? -2 - axis : -1; }
  bool refit_allowed(double travelled) const { return travelled < until - static_cast<double>(refit_slack); }
  // Points clipped at `travelled` may be refit until the travels have grown by `margin` more
  // (and never past the axis' own bound).
  void allow_refit(double travelled, double margin) {
    const double slack = std::max(until - (travelled + margin), 0.0);
    float rounded = static_cast<float>(slack);
    if (static_cast<double>(rounded) < slack) rounded = std::nextafter(rounded, std::numeric_limits<float>::infinity());
    refit_slack = rounded;
  }
};
static_assert(sizeof(PartBudget) == 16);

class PairBudgets {
 public:
  // True while the budgets belong to the current list (cleared at every rebuild).
  bool matches(const PairList& list) const { return body_.size() == list.entries(); }
  // Zero budgets (every pair is tested) for each entry of `list` and each pair of its bodies' parts.
  void reset(const PairList& list, const ParticleStore& p, const std::vector<CompositeShape>& shapes);
  void clear() { body_.clear(); }
  double* body() { return body_.data(); }
  // Entry e's part-pair budgets, row-major: part a of i with part b of j at a * parts(j) + b.
  PartBudget* parts(std::size_t e) { return part_.data() + part_begin_[e]; }
  // Asks for the lines of entry e's part-pair budgets (a cross pair's 64 bytes may span two).
  void prefetch_parts(std::size_t e) const {
    __builtin_prefetch(part_.data() + part_begin_[e]);
    __builtin_prefetch(part_.data() + part_begin_[e + 1] - 1);
  }

 private:
  std::vector<double> body_;
  std::vector<std::uint32_t> part_begin_;
  std::vector<PartBudget> part_;
};

}  // namespace talus
