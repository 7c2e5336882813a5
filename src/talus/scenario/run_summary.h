#pragma once
// What summary.json says of a scenario's world as it stands: time, steps, counts, energies,
// wall forces, threads and ranks, the wall time of each phase of the step, and the scenario's
// derived quantities. The run loop adds what belongs to the run (stop reason, wall time,
// checkpoints, removed particles, the observers' figures); the Python module's
// Simulation.summary() starts from the same part.
#include <nlohmann/json.hpp>

#include "talus/scenario/scenario.h"

namespace talus {

// `d`: the world's diagnostics now (World::diagnostics, a collective call when distributed).
nlohmann::json world_summary(const Scenario& scenario, const Diagnostics& d);

}  // namespace talus
