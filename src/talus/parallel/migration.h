#pragma once
// Particles that crossed a cut move to the rank whose slab they entered, at a rebuild, with the
// contact memories that rank will need: every carried memory of a pair that is no longer held
// wholly by one rank is copied to the neighbours, and each rank keeps the memories of the pairs
// with a particle it owns, keyed by that particle's global id (PairList::restore_memory looks
// a record up in its first particle's row).
#include <cstddef>

#include "talus/body/particles.h"
#include "talus/collide/pair_list.h"
#include "talus/parallel/slab_decomposition.h"
#include "talus/world/wall_contacts.h"

namespace talus {

struct MigrationCount {
  std::size_t left = 0, arrived = 0;
};

// Owned particles must be wrapped and ghosts dropped. A particle may move one slab per
// rebuild (it moves less than half a skin between rebuilds, and slabs are wider).
// `wall_memories` (keyed by global id) go with their particles and come with the arrivals.
// Shaped bodies' contact points travel too when `wall_points` is given (one list per wall
// memory) and `carried.points` holds one list per record; after the call `carried` holds its
// points (entry k being record k) and `wall_points` those of the new `wall_memories`.
MigrationCount migrate(ParticleStore& particles, const SlabDecomposition& slabs, CarriedContacts& carried,
                       std::vector<WallMemoryRecord>& wall_memories, const MemoryLayout& layout,
                       std::size_t gid_limit, std::vector<SubContactList>* wall_points = nullptr);

}  // namespace talus
