#pragma once
// What the neighbour search of a World keeps from one build to the next: the cells, the
// particle-pair and particle-wall lists with their contact memories, the periodic images, and
// where everything stood at the build, which decides the next rebuild (half the skin travelled,
// a wall moved) and lets the memories follow their particles by global id.
#include <cstdint>
#include <vector>

#include "talus/collide/cell_grid.h"
#include "talus/collide/pair_list.h"
#include "talus/math/vec3.h"
#include "talus/world/periodic_ghosts.h"
#include "talus/world/wall_contacts.h"

namespace talus {

struct NeighborLists {
  CellGrid grid;
  PairList pairs;              ///< half list of particle pairs, with their memories
  WallContactList walls;       ///< particle-wall candidates, with their memories
  PeriodicGhosts ghosts;       ///< periodic images of owned particles
  CarriedContacts carried;         ///< rebuild scratch: the memories the new list takes over
  std::vector<CellCoord> cell_of;  ///< rebuild scratch: the cell of each particle and ghost

  // The last build.
  std::vector<std::uint32_t> gid_at_build;  ///< owned and ghost ids, for the next carry-over
  std::vector<Vec3> position_at_build;      ///< m, owned particles
  std::vector<Vec3> wall_origin_at_build;   ///< m, per wall
  std::vector<char> wall_active_at_build;   ///< per wall
  double time_at_build = 0;                 ///< s (wall positions)
  double skin = 0;                          ///< m
  double max_displacement = 0;              ///< m, the largest travel since the build
};

}  // namespace talus
