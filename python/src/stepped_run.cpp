// talus._talus.SteppedRun: a scenario loaded and stepped on request (scenario/stepped_run.h),
// with its particle arrays as NumPy views. The talus.Simulation class wraps it.
#include <omp.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.h"
#include "json_to_python.h"
#include "particle_views.h"
#include "talus/io/checkpoint_file.h"
#include "talus/io/scenario_file.h"
#include "talus/scenario/stepped_run.h"

namespace talus::python {

namespace {

// Ctrl-C in Python raises KeyboardInterrupt after the batch in progress.
void raise_pending_signals() {
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
}

void set_threads(std::optional<int> threads) {
  if (!threads) return;
  if (*threads < 1) throw py::value_error("threads must be at least 1");
  omp_set_num_threads(*threads);
}

class PySteppedRun {
 public:
  explicit PySteppedRun(std::shared_ptr<SteppedRun> run) : run_(run), views_(run->world(), run) {}

  // `talus run FILE --set KEY=VALUE ...`, optionally `--restart CHECKPOINT`.
  static PySteppedRun load(const std::string& path, const std::vector<std::string>& overrides,
                           const std::optional<std::string>& restart, std::optional<int> threads) {
    set_threads(threads);
    io::ScenarioFile file = io::ScenarioFile::from_file(path);
    for (const std::string& o : overrides) file.set_override(o);
    auto run = std::make_shared<SteppedRun>(file);
    if (restart) run->restore(io::read_checkpoint(*restart), *restart);
    return PySteppedRun(run);
  }

  // `talus resume`: the scenario stored in the checkpoint, from the checkpoint's state.
  static PySteppedRun resume(const std::string& checkpoint_path, std::optional<int> threads) {
    set_threads(threads);
    const io::Checkpoint checkpoint = io::read_checkpoint(checkpoint_path);
    io::ScenarioFile file = io::ScenarioFile::from_string(checkpoint.scenario_toml, checkpoint_path + ":/scenario");
    auto run = std::make_shared<SteppedRun>(file);
    run->restore(checkpoint, checkpoint_path);
    return PySteppedRun(run);
  }

  // SteppedRun::run: at most `steps` steps, up to `until`; returns the steps run.
  std::uint64_t run(std::uint64_t steps, double until) {
    views_.detach();
    return run_->run(steps, until, raise_pending_signals);
  }

  py::array view(ParticleField field) { return views_.view(field); }

  py::object summary() {
    views_.detach();
    return to_python(run_->summary());
  }
  Snapshot snapshot() {
    views_.detach();
    return run_->snapshot();
  }
  void checkpoint(const std::filesystem::path& path) {
    views_.detach();
    run_->write_checkpoint(path);
  }

  const World& world() const { return run_->world(); }
  const Scenario& scenario() const { return run_->scenario(); }
  const std::string& scenario_toml() const { return run_->scenario_toml(); }

 private:
  std::shared_ptr<SteppedRun> run_;
  ParticleViews views_;
};

}  // namespace

void bind_stepped_run(py::module_& m) {
  py::class_<PySteppedRun> c(m, "SteppedRun");
  c.def_static("load", &PySteppedRun::load, py::arg("path"), py::arg("overrides"), py::arg("restart"),
               py::arg("threads"))
      .def_static("resume", &PySteppedRun::resume, py::arg("checkpoint"), py::arg("threads"))
      .def("run", &PySteppedRun::run, py::arg("steps"), py::arg("until"))
      .def("summary", &PySteppedRun::summary)
      .def("snapshot", &PySteppedRun::snapshot)
      .def("checkpoint", &PySteppedRun::checkpoint, py::arg("path"))
      .def_property_readonly("time", [](const PySteppedRun& r) { return r.world().time(); })
      .def_property_readonly("steps", [](const PySteppedRun& r) { return r.world().step_count(); })
      .def_property_readonly("dt", [](const PySteppedRun& r) { return r.world().settings().time_step; })
      .def_property_readonly("end_time", [](const PySteppedRun& r) { return r.scenario().control.end_time; })
      .def_property_readonly("gravity",
                             [](const PySteppedRun& r) {
                               const Vec3 g = r.world().settings().gravity;
                               return std::vector<double>{g.x, g.y, g.z};
                             })
      .def_property_readonly("particle_count", [](const PySteppedRun& r) { return r.world().owned_count(); })
      .def_property_readonly("species_names", [](const PySteppedRun& r) { return r.scenario().species; })
      .def_property_readonly("wall_names",
                             [](const PySteppedRun& r) {
                               std::vector<std::string> names;
                               for (const Wall& w : r.world().walls()) names.push_back(w.name);
                               return names;
                             })
      .def_property_readonly("observers",
                             [](const PySteppedRun& r) {
                               std::vector<std::string> names;
                               for (const auto& o : r.scenario().observers) names.push_back(o->name());
                               return names;
                             })
      .def_property_readonly("scenario_toml", &PySteppedRun::scenario_toml)
      .def(
          "measure_collapse",  // with the footprints of this World's shapes
          [](const PySteppedRun& r, const Snapshot& initial, const Snapshot& final, double initial_length,
             double box_length, double width, std::optional<double> particle_size, double pixel) {
            return measure_collapse(initial, final, {initial_length, box_length, width, particle_size, pixel},
                                    &r.world().shapes());
          },
          py::arg("initial"), py::arg("final"), py::arg("initial_length"), py::arg("box_length"), py::arg("width"),
          py::arg("particle_size"), py::arg("pixel"));
  const std::pair<const char*, ParticleField> fields[] = {
      {"positions", ParticleField::position},   {"velocities", ParticleField::velocity},
      {"angular_velocities", ParticleField::angular_velocity},
      {"orientations", ParticleField::orientation}, {"radii", ParticleField::radius},
      {"masses", ParticleField::mass},          {"ids", ParticleField::id},
      {"species", ParticleField::species}};
  for (const auto& [name, field] : fields)
    c.def_property_readonly(name, [field = field](PySteppedRun& r) { return r.view(field); });
}

}  // namespace talus::python
