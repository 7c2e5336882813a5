#pragma once
// Fields coarse-grained from the pieces of a system spread over ranks, summed into the whole
// system's. Every field but the kinetic stress is a sum over particles and contacts, so the
// pieces add; the kinetic stress is formed again from the summed fields (Weinhart et al. 2012,
// Eqs. 29-30 pointwise: sum m v v W - p p / rho).
#include "talus/analysis/cg_fields.h"
#include "talus/parallel/communicator.h"

namespace talus {

// Collective: every rank passes its piece's fields, on the same grid, and gets the sum.
void sum_over_ranks(CgFields& fields, const Communicator& ranks);

}  // namespace talus
