// talus.Snapshot: the particles and contacts of one instant (analysis/snapshot.h), from a running
// Simulation or a snapshot file (io/snapshot_file.h). Its arrays are copies, in global id order.
#include <string>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.h"
#include "numpy_values.h"
#include "talus/io/json_file.h"
#include "talus/io/snapshot_file.h"
#include "talus/io/snapshot_json.h"

namespace talus::python {

namespace {

// One value per particle, or per contact.
template <class S, class Record, class Get>
py::array_t<S> column(const std::vector<Record>& records, Get get) {
  py::array_t<S> a(static_cast<py::ssize_t>(records.size()));
  auto out = a.template mutable_unchecked<1>();
  for (std::size_t k = 0; k < records.size(); ++k) out(k) = static_cast<S>(get(records[k]));
  return a;
}

// One 3-vector per particle, or per contact.
template <class Record, class Get>
py::array_t<double> vectors(const std::vector<Record>& records, Get get) {
  py::array_t<double> a({static_cast<py::ssize_t>(records.size()), py::ssize_t{3}});
  auto out = a.mutable_unchecked<2>();
  for (std::size_t k = 0; k < records.size(); ++k) {
    const Vec3 v = get(records[k]);
    out(k, 0) = v.x;
    out(k, 1) = v.y;
    out(k, 2) = v.z;
  }
  return a;
}

template <class S, auto Member>
py::array_t<S> particle_column(const Snapshot& s) {
  return column<S>(s.particles, [](const ParticleRecord& p) { return p.*Member; });
}

template <auto Member>
py::array_t<double> particle_vectors(const Snapshot& s) {
  return vectors(s.particles, [](const ParticleRecord& p) { return p.*Member; });
}

py::array_t<double> orientations(const Snapshot& s) {
  py::array_t<double> a({static_cast<py::ssize_t>(s.particles.size()), py::ssize_t{4}});
  auto out = a.mutable_unchecked<2>();
  for (std::size_t k = 0; k < s.particles.size(); ++k) {
    const Quat& q = s.particles[k].orientation;
    out(k, 0) = q.w;
    out(k, 1) = q.x;
    out(k, 2) = q.y;
    out(k, 3) = q.z;
  }
  return a;
}

// Every contact point: particles i and j by global id (j = -1 against a wall, `wall` naming
// it, -1 otherwise), the force on i split along the normal (pointing from j or the wall
// towards i) and across it.
py::dict contacts(const Snapshot& s) {
  const auto& c = s.contacts;
  const auto& p = s.particles;
  py::dict d;
  d["i"] = column<std::int64_t>(c, [&](const ContactRecord& r) { return p[r.i].id; });
  d["j"] = column<std::int64_t>(c, [&](const ContactRecord& r) { return r.j < 0 ? std::int64_t{-1} : p[r.j].id; });
  d["wall"] = column<std::int32_t>(c, [](const ContactRecord& r) { return r.j < 0 ? r.wall : -1; });
  d["point"] = vectors(c, [](const ContactRecord& r) { return r.point; });
  d["normal"] = vectors(c, [](const ContactRecord& r) { return r.normal; });
  d["force"] = vectors(c, [](const ContactRecord& r) { return r.force; });
  d["normal_force"] = vectors(c, [](const ContactRecord& r) { return dot(r.force, r.normal) * r.normal; });
  d["tangential_force"] =
      vectors(c, [](const ContactRecord& r) { return r.force - dot(r.force, r.normal) * r.normal; });
  d["overlap"] = column<double>(c, [](const ContactRecord& r) { return r.overlap; });
  return d;
}

}  // namespace

py::class_<Snapshot> bind_snapshot(py::module_& m) {
  py::class_<Snapshot> c(m, "Snapshot", "Particles and contacts at one instant; arrays are copies in global id order.");
  c.def_readonly("time", &Snapshot::time, "s")
      .def_property_readonly("gravity", [](const Snapshot& s) { return to_numpy(s.gravity); }, "m/s^2")
      .def_property_readonly("domain_min", [](const Snapshot& s) { return to_numpy(s.domain_min); }, "m")
      .def_property_readonly("domain_max", [](const Snapshot& s) { return to_numpy(s.domain_max); }, "m")
      .def_property_readonly("periodic",
                             [](const Snapshot& s) { return std::vector<bool>(s.periodic, s.periodic + 3); })
      .def_property_readonly("particle_count", [](const Snapshot& s) { return s.particles.size(); })
      .def_property_readonly("ids", &particle_column<std::uint32_t, &ParticleRecord::id>)
      .def_property_readonly("species", &particle_column<std::int32_t, &ParticleRecord::species>)
      .def_property_readonly("shapes", &particle_column<std::int32_t, &ParticleRecord::shape>)
      .def_property_readonly("fixed", &particle_column<bool, &ParticleRecord::fixed>)
      .def_property_readonly("masses", &particle_column<double, &ParticleRecord::mass>, "kg")
      .def_property_readonly("radii", &particle_column<double, &ParticleRecord::radius>, "m, bounding radius")
      .def_property_readonly("volumes", &particle_column<double, &ParticleRecord::volume>, "m^3")
      .def_property_readonly("positions", &particle_vectors<&ParticleRecord::position>, "m, centre of mass")
      .def_property_readonly("velocities", &particle_vectors<&ParticleRecord::velocity>, "m/s")
      .def_property_readonly("angular_velocities", &particle_vectors<&ParticleRecord::angular_velocity>,
                             "rad/s, world frame")
      .def_property_readonly("orientations", &orientations, "w, x, y, z: body to world")
      .def("contacts", &contacts,
           "Every contact point: i, j (global ids; j = -1 for a wall), wall, point, normal (from j towards i), "
           "force, normal_force, tangential_force (N, on i), overlap.")
      .def("save", [](const Snapshot& s, const std::filesystem::path& path) { io::write_snapshot_file(path, s); },
           py::arg("path"));
  // A snapshot file, or the JSON of a dam break's states (state_before_gate.json,
  // state_final.json: particles only).
  m.def(
      "read_snapshot",
      [](const std::filesystem::path& path) {
        return path.extension() == ".json" ? snapshot_from_json(io::read_json(path)) : io::read_snapshot_file(path);
      },
      py::arg("path"));
  m.def("snapshot_files", &io::snapshot_files, py::arg("results_dir"));
  return c;
}

}  // namespace talus::python
