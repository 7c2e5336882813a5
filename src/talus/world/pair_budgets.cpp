#include "talus/world/pair_budgets.h"

namespace talus {

void PairBudgets::reset(const PairList& list, const ParticleStore& p, const std::vector<CompositeShape>& shapes) {
  // A sphere (shape 0) is a one-part composite.
  auto parts_of = [&](std::size_t i) -> std::uint32_t {
    return p.shape[i] == 0 ? 1u : static_cast<std::uint32_t>(shapes[p.shape[i]].parts.size());
  };
  body_.assign(list.entries(), 0.0);
  part_begin_.resize(list.entries() + 1);
  std::uint32_t n = 0;
  for (std::size_t i = 0; i < list.rows(); ++i)
    for (std::uint32_t e = list.row_begin(i); e < list.row_end(i); ++e) {
      part_begin_[e] = n;
      n += parts_of(i) * parts_of(list.neighbor(e));
    }
  part_begin_[list.entries()] = n;
  part_.assign(n, PartBudget{});
}

}  // namespace talus
