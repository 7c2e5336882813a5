#pragma once
// A World's share of a run spread over ranks (World::distribute): its box in the grid of ranks,
// the halo of copies from its neighbours, the migration's working arrays, and how many particles have changed rank.
#include <cstdint>

#include "talus/parallel/halo_exchange.h"
#include "talus/parallel/migration.h"
#include "talus/parallel/rank_grid.h"

namespace talus {

struct SpreadOverRanks {
  RankGrid ranks;  ///< comm == nullptr: not distributed
  HaloExchange halo;
  MigrationScratch migration;  ///< kept between rebuilds (migration.h)
  std::uint64_t migrated = 0;  ///< particles this rank sent to others
};

}  // namespace talus
