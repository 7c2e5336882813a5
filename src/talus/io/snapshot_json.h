#pragma once
// A snapshot's particles as JSON arrays (contacts are not kept): what an observer stores in a
// checkpoint to resume analyses that compare the end of a run with an earlier state.
#include <nlohmann/json.hpp>

#include "talus/analysis/snapshot.h"

namespace talus {

nlohmann::json snapshot_to_json(const Snapshot& snapshot);
Snapshot snapshot_from_json(const nlohmann::json& json);

}  // namespace talus
