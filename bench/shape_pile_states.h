#pragma once
// The cached states of the shape piles (shape_pile_cases.h), each generated once into
// ShapePileOptions::cache and loaded from there afterwards:
//   settled : the bodies placed at random, then settle_time under gravity (a fixed number of
//             steps, not "until slower than a threshold": the cost is known beforehand, and a
//             file names one recipe);
//   flowing : the settled pile flow_time after the x+ wall went (the loaded world has that
//             wall removed too).
// Files keep the particles and the time, not the contact memory: warm a loaded state up before
// timing it.
#include <memory>

#include "shape_pile.h"
#include "shape_pile_cases.h"
#include "talus/world/world.h"

namespace talus::bench {

// Each sets *seconds_generating to the wall time spent generating the state (0 if cached).
std::unique_ptr<World> load_or_settle(const ShapePileOptions& o, const ShapePileCase& c, double* seconds_generating);
std::unique_ptr<World> load_or_flow(const ShapePileOptions& o, const ShapePileCase& c, double* seconds_generating);

}  // namespace talus::bench
