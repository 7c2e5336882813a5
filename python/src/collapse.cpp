// Dam-break measurements (analysis/collapse_*.h) of two snapshots, the column before the gate
// opened and the pile at rest, as `talus run` reports them in summary.json; and the mean speeds
// and centre of mass of one snapshot.
#include <algorithm>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "numpy_values.h"
#include "talus/analysis/collapse_centre_of_mass.h"
#include "talus/analysis/collapse_footprint.h"
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

py::dict height_dict(const collapse::HeightProfile& h) {
  py::dict d;
  d["mean"] = h.mean;
  d["q1"] = h.q1;
  d["median"] = h.median;
  d["q3"] = h.q3;
  d["y"] = to_numpy(h.y);
  d["h"] = to_numpy(h.h);
  return d;
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
  py::dict d;
  d["H0"] = m.initial_height.mean;
  d["final_height"] = m.final_height.mean;
  d["runout"] = m.runout.nominal;
  d["runout_low"] = m.runout.low;
  d["runout_high"] = m.runout.high;
  d["runout_reached_box_end"] = m.runout.reached_frame_end;
  d["aspect_ratio"] = m.aspect_ratio;
  d["runout_ratio"] = m.runout_ratio;
  d["runout_ratio_low"] = m.runout_ratio_low;
  d["runout_ratio_high"] = m.runout_ratio_high;
  d["height_ratio"] = m.height_ratio;
  d["height_ratio_low"] = m.height_ratio_low;
  d["height_ratio_high"] = m.height_ratio_high;
  d["com_initial"] = to_numpy(m.centre_of_mass.initial);
  d["com_final"] = to_numpy(m.centre_of_mass.final);
  d["com_displacement"] = to_numpy(m.centre_of_mass.displacement);
  d["com_ratio"] = m.centre_ratio;
  d["regime"] = collapse::to_string(m.regime.regime);
  d["displaced_particles"] = m.regime.displaced;
  d["displaced_fraction"] = m.regime.displaced_fraction;
  d["particle_size"] = setup.particle_size;
  d["initial_height_profile"] = height_dict(m.initial_height);
  d["final_height_profile"] = height_dict(m.final_height);
  d["runout_profile"] = py::dict(py::arg("x") = to_numpy(m.runout.profile.x),
                                 py::arg("intensity") = to_numpy(m.runout.profile.intensity));
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
