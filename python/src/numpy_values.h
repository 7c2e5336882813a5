#pragma once
// Engine values as NumPy arrays (copies).
#include <vector>

#include <pybind11/numpy.h>

#include "talus/math/vec3.h"

namespace talus::python {

static_assert(sizeof(Vec3) == 3 * sizeof(double), "a Vec3 is read as three doubles");
inline pybind11::array_t<double> to_numpy(const Vec3& v) { return pybind11::array_t<double>(3, &v.x); }

inline pybind11::array_t<double> to_numpy(const std::vector<double>& values) {
  return pybind11::array_t<double>(static_cast<pybind11::ssize_t>(values.size()), values.data());
}

}  // namespace talus::python
