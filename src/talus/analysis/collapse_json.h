#pragma once
// A dam break's measurements (collapse_summary.h) as one flat JSON object, the single naming
// that summary.json and the Python module share: scalars, the centre of mass as [x, y, z], and
// the height and runout profiles as arrays.
#include <nlohmann/json.hpp>

#include "talus/analysis/collapse_summary.h"

namespace talus::collapse {

nlohmann::json collapse_measures_json(const CollapseMeasures& m);

}  // namespace talus::collapse
