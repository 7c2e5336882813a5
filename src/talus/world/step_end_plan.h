#pragma once
// How each owned particle of a sphere world ends its step inside the force pass
// (World::compute_forces_ending_step), decided at every rebuild (World::mark_step_ends): as soon
// as its slab's rows are done, or late, once the ghost fold and the walls have added to it.
#include <cstdint>
#include <vector>

#include "talus/integrate/velocity_verlet.h"

namespace talus {

struct StepEndPlan {
  std::vector<StepEndKind> kind;    ///< per owned particle
  std::vector<std::uint32_t> late;  ///< the owned particles whose step ends late
  // Without walls, owners of ghosts (numbered as by PeriodicGhosts::owner_at) whose ghosts all
  // lie in their own slab end their step with that slab, in the pair pass: inline_owner from
  // inline_owner_start[s] for slab s. The others (late_owner) end theirs later in the same
  // parallel region. With walls both lists are empty.
  std::vector<std::uint32_t> inline_owner, inline_owner_start, late_owner;
  bool late_owners_in_first_slab = true;  ///< all of late_owner (World::pair_forces relies on it)
  bool ghosts_fresh = false;              ///< ghosts were refreshed as their owners ended the step
};

}  // namespace talus
