// Dam-break measurements (analysis/collapse_*.h) of two snapshots, the column before the gate
// opened and the pile at rest, as `talus run` reports them in summary.json; and the mean speeds
// and centre of mass of one snapshot.
#include <algorithm>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "json_to_python.h"
#include "numpy_values.h"
#include "talus/analysis/collapse_centre_of_mass.h"
#include "talus/analysis/collapse_footprint.h"
#include "talus/analysis/collapse_json.h"
#include "talus/analysis/collapse_speed.h"
#include "talus/analysis/collapse_summary.h"
#include "talus/scenario/dam_break_observer.h"

namespace talus::python {

namespace {

// Footprints of the snapshot's particles: their shapes' parts when the shapes are known, else
// each one's bounding sphere (exact for spheres, larger than any other shape).
std::vector<collapse::Footprint> footprints(const Snapshot& s, const std::vector<CompositeShape>* shapes) {
  return shapes ? particle_footprints(s, footprint_templates(*shapes)) : collapse::bounding_sphere_footprints(s);
}

}  // namespace

py::dict measure_collapse(const Snapshot& initial, const Snapshot& final, const CollapseGeometry& geometry,
                          const std::vector<CompositeShape>* shapes) {
  collapse::CollapseSetup setup;
  setup.initial_length = geometry.initial_length;
  setup.box_length = geometry.box_length;
  setup.width = geometry.width;
  setup.pixel = geometry.pixel;
  setup.particle_size = geometry.particle_size.value_or(0);
  if (!geometry.particle_size)  // as the dam break's: the largest mobile bounding diameter
    for (const ParticleRecord& p : initial.particles)
      if (!p.fixed) setup.particle_size = std::max(setup.particle_size, 2 * p.radius);
  const collapse::CollapseMeasures m =
      collapse::measure_collapse(initial, footprints(initial, shapes), final, footprints(final, shapes), setup);
  // The names summary.json uses (collapse_json.h), with vectors and profiles as NumPy arrays.
  py::dict d = to_python(collapse::collapse_measures_json(m));
  d["particle_size"] = setup.particle_size;
  const auto as_numpy = [](py::handle values) { return py::array_t<double, py::array::forcecast>::ensure(values); };
  for (const char* key : {"com_initial", "com_final", "com_displacement"}) d[key] = as_numpy(d[key]);
  for (const char* key : {"initial_height_profile", "final_height_profile"})
    for (const char* array : {"y", "h"}) d[key][array] = as_numpy(d[key][array]);
  for (const char* array : {"x", "intensity"}) d["runout_profile"][array] = as_numpy(d["runout_profile"][array]);
  return d;
}

void bind_collapse(py::module_& m, py::class_<Snapshot>& snapshot) {
  m.def(
      "measure_collapse",
      [](const Snapshot& initial, const Snapshot& final, double initial_length, double box_length, double width,
         std::optional<double> particle_size, double pixel) {
        return measure_collapse(initial, final, {initial_length, box_length, width, particle_size, pixel}, nullptr);
      },
      py::arg("initial"), py::arg("final"), py::arg("initial_length"), py::arg("box_length"), py::arg("width"),
      py::arg("particle_size"), py::arg("pixel"));
  snapshot
      .def("mean_speeds",
           [](const Snapshot& s) {
             const collapse::MeanSpeeds v = collapse::mean_speeds(s);
             return py::dict(py::arg("translational") = v.translational, py::arg("angular") = v.angular);
           })
      .def("centre_of_mass", [](const Snapshot& s) { return to_numpy(collapse::centre_of_mass(s)); });
}

}  // namespace talus::python
