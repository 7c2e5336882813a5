#pragma once
// A World's share of a run spread over ranks (World::distribute): its slab, the halo of copies
// from the rank above, and how many particles have changed rank.
#include <cstdint>

#include "talus/parallel/halo_exchange.h"
#include "talus/parallel/slab_decomposition.h"

namespace talus {

struct SpreadOverRanks {
  SlabDecomposition slabs;  ///< comm == nullptr: not distributed
  HaloExchange halo;
  std::uint64_t migrated = 0;  ///< particles this rank sent to others
};

}  // namespace talus
