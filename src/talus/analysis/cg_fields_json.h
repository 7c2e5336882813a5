#pragma once
// Coarse-grained fields as JSON and back, bit for bit (nlohmann prints doubles round-trip):
// how a chute run's time averages travel through a checkpoint.
#include <nlohmann/json.hpp>

#include "talus/analysis/cg_fields.h"

namespace talus {

nlohmann::json to_json(const CgFields& fields);
// Throws std::invalid_argument on a malformed document.
CgFields cg_fields_from_json(const nlohmann::json& j);

}  // namespace talus
