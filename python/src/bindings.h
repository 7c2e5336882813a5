#pragma once
// The pieces of the talus._talus extension, each bound by its own file; module.cpp calls them.
#include <pybind11/pybind11.h>

#include "talus/analysis/snapshot.h"

namespace talus::python {

namespace py = pybind11;

void bind_errors(py::module_& m);                        // errors.cpp
py::class_<Snapshot> bind_snapshot(py::module_& m);      // snapshot.cpp
void bind_analyses(py::class_<Snapshot>& snapshot);      // analyses.cpp
void bind_stepped_run(py::module_& m);                   // stepped_run.cpp

}  // namespace talus::python
