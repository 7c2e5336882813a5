#pragma once
// The pieces of a snapshot that the ranks of a distributed world hold, joined on every rank or
// on one.
#include <cstddef>

#include "talus/analysis/snapshot.h"
#include "talus/parallel/communicator.h"

namespace talus {

// `piece` holds this rank's particles and the contacts of the pairs it lists, naming particles
// by global id (below `id_limit`). The result is the whole system: particles in global id
// order, contacts rank by rank, named by record as in any snapshot. `root` >= 0: on that rank
// only; the others get the piece's header (time, box) without particles or contacts.
Snapshot gather_snapshot(const Snapshot& piece, const Communicator& comm, std::size_t id_limit, int root = -1);

}  // namespace talus
