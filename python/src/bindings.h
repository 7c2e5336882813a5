#pragma once
// The pieces of the talus._talus extension, each bound by its own file; module.cpp calls them.
#include <optional>
#include <vector>

#include <pybind11/pybind11.h>

#include "talus/analysis/snapshot.h"
#include "talus/shape/composite_shape.h"

namespace talus::python {

namespace py = pybind11;

void bind_errors(py::module_& m);                        // errors.cpp
py::class_<Snapshot> bind_snapshot(py::module_& m);      // snapshot.cpp
void bind_analyses(py::class_<Snapshot>& snapshot);      // analyses.cpp
void bind_collapse(py::module_& m, py::class_<Snapshot>& snapshot);  // collapse.cpp
void bind_stepped_run(py::module_& m);                   // stepped_run.cpp

// The geometry of a dam break (analysis/collapse_summary.h, CollapseSetup): the column fills x in
// [0, initial_length] against the back wall x = 0, the box spans x in [0, box_length] and y in
// [0, width] (m); particle_size (m) scales the regime's tolerances, by default the largest
// bounding diameter; pixel (m) is the camera's (Huet et al. 2021, Sec. III C: 0.43 mm).
struct CollapseGeometry {
  double initial_length = 0, box_length = 0, width = 0;
  std::optional<double> particle_size;
  double pixel = 0.43e-3;
};
// The dam break's measurements, with footprints from `shapes` (the World's) or, without, each
// particle's bounding sphere.
py::dict measure_collapse(const Snapshot& initial, const Snapshot& final, const CollapseGeometry& geometry,
                          const std::vector<CompositeShape>* shapes);

}  // namespace talus::python
