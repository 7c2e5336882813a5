#pragma once
// Everything a World needs to carry on exactly where it was, as plain data: what a checkpoint
// stores (io/checkpoint_file.h). The scenario supplies the rest (settings, shapes, contact
// table); walls are stored because a run may move or remove them.
//
// How bit-for-bit restarts work: the neighbour lists are not stored but rebuilt from the
// positions of their last build (`position_at_build`, in the particles' current order, which
// is the order of that build). The build is a pure function of those positions, the order and
// the per-particle constants, so the restored World holds the same lists, entry for entry, and
// sums forces in the same order as the World that never stopped. The contact memories are then
// put back entry by entry; each entry's global ids are stored to check that the lists match.
#include <array>
#include <cstdint>
#include <vector>

#include "talus/body/particles.h"
#include "talus/collide/pair_list.h"
#include "talus/contact/contact_law.h"
#include "talus/world/sub_contacts.h"
#include "talus/world/wall.h"

namespace talus {

struct WorldState {
  // Owned particles, in their current order (ghosts are derived); those of a distributed world
  // rank after rank.
  ParticleStore particles;
  // The ranks the state was gathered from. Above 1 the particles are in no single build's
  // order: a restore on another number of ranks builds the lists afresh and finds each memory by
  // the global ids of its pair, so the run goes on to round-off, not to the bit. On as many
  // ranks, each rank takes its share back (`layout`) and replays its last build: bit for bit.
  std::uint64_t ranks = 1;
  struct RankLayout {
    int axis = 0;                ///< the pair list's slab axis, a cut one
    bool rebalance = false;      ///< the cuts follow the particles
    double min_width = 0;        ///< m, no slab narrower
    std::array<std::vector<double>, 3> cut;  ///< m, per axis those of the last build; empty along an uncut axis
    // Each rank's share of the joined arrays: particles (and position_at_build), particle-pair
    // entries, particle-wall entries.
    std::vector<std::uint64_t> particles, pair_entries, wall_entries;
  };
  RankLayout layout;  ///< no cuts for one rank and in files that predate it
  // >= 0: the arrays hold only that rank's share of the joined ones (layout), as that rank
  // read them from the file (io::read_checkpoint_share), not the whole state.
  int share_of_rank = -1;
  // False on the ranks other than 0 of a distributed world: rank 0 gathers the pieces and
  // writes the checkpoint, so the others keep only their own piece, never a copy of the whole.
  bool whole = true;
  bool fits_ranks(std::uint64_t n) const;  ///< gathered from n > 1 ranks, with their layout
  std::uint32_t next_gid = 0;
  double time = 0;                  ///< s
  std::uint64_t steps = 0;
  std::uint64_t rebuilds = 0;
  Vec3 gravity;                     ///< m/s^2 (a run may tilt it)
  TangentialModel tangential_model = TangentialModel::memory;  ///< a run may switch it
  std::vector<Wall> walls;
  std::vector<Vec3> wall_force;     ///< N, per wall, at the last step

  // The last neighbour-list build.
  std::vector<Vec3> position_at_build;  ///< m, owned particles, current order
  double time_at_build = 0;             ///< s, wall positions of that build
  double skin = 0;                      ///< m

  // Particle-pair list entries: global ids of (row, neighbour), memory, contact points.
  std::vector<std::uint32_t> pair_gid_i, pair_gid_j;
  ContactMemory pair_memory;
  std::vector<SubContactList> pair_sub;  ///< per entry when the run has rigid shapes, else empty

  // Particle-wall list entries: particle global id, wall index, memory, last force, contact points.
  std::vector<std::uint32_t> wall_gid;
  std::vector<std::int32_t> wall_index;
  ContactMemory wall_memory;
  std::vector<Vec3> wall_entry_force;    ///< N, force on the wall per entry
  std::vector<SubContactList> wall_sub;
};

}  // namespace talus
