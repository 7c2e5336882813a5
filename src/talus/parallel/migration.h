#pragma once
// Particles that crossed a cut move to the rank whose box they entered, at a rebuild, with the
// contact memories that rank will need. They move one cut axis after the other (a particle
// across a corner passes through a neighbour), and every carried memory of a pair that is not
// held wholly by one rank goes along to the neighbours at each stage; in the end each rank
// keeps the memories of the pairs with a particle it owns, keyed by that particle's global id
// (PairList::restore_memory looks a record up in its first particle's row).
#include <cstddef>

#include "talus/body/gid_index.h"
#include "talus/body/particles.h"
#include "talus/collide/pair_list.h"
#include "talus/parallel/rank_grid.h"
#include "talus/world/wall_contacts.h"

namespace talus {

struct MigrationCount {
  std::size_t left = 0, arrived = 0;
};

// The working arrays of a migration, kept by the caller from one rebuild to the next: arrays
// the size of every carried memory, allocated afresh, would map their pages anew at each
// rebuild (on a virtual machine, half the migration's time).
struct MigrationScratch {
  GidIndex owned, destination;
  std::vector<CarriedRecord> records;
  std::vector<SubContactList> record_points;
  std::vector<std::uint32_t> order, leaving;
};

// Owned particles must be wrapped and ghosts dropped. A particle may move one slab along each
// axis per rebuild (it moves less than half a skin between rebuilds, and slabs are wider).
// `wall_memories` (keyed by global id) go with their particles and come with the arrivals.
// Shaped bodies' contact points travel too when `wall_points` is given (one list per wall
// memory) and `carried.points` holds one list per record; after the call `carried` holds its
// points (entry k being record k) and `wall_points` those of the new `wall_memories`.
MigrationCount migrate(ParticleStore& particles, const RankGrid& ranks, CarriedContacts& carried,
                       std::vector<WallMemoryRecord>& wall_memories, const MemoryLayout& layout,
                       MigrationScratch& scratch,
                       std::vector<SubContactList>* wall_points = nullptr);

// The start of a run built on the first rank alone (WorldSettings::particles_on_first_rank):
// rank 0 holds every particle, the others none; each particle goes straight to the rank whose
// box holds its position wrapped into `domain`, in the order rank 0 holds them. A world that
// has not stepped has no contact memory to send along. Collective; returns the particles rank
// 0 sent.
std::size_t scatter_from_first_rank(ParticleStore& particles, const RankGrid& ranks, const Domain& domain);

}  // namespace talus
