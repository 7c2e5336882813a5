#pragma once
// nlohmann::json as plain Python values: dict, list, str, int, float, bool, None.
#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

namespace talus::python {

pybind11::object to_python(const nlohmann::json& value);

}  // namespace talus::python
