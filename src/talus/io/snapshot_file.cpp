#include "talus/io/snapshot_file.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>

#include "talus/io/atomic_file.h"
#include "talus/io/flat_arrays.h"
#include "talus/io/hdf5_file.h"
#include "talus/io/input_error.h"

namespace talus::io {

namespace {

constexpr const char* kFormat = "talus-snapshot";

// One field of every record (particle or contact), as a dataset's column.
template <class T, class Record, class Get>
std::vector<T> column(const std::vector<Record>& records, Get get) {
  std::vector<T> out;
  out.reserve(records.size());
  for (const Record& r : records) out.push_back(get(r));
  return out;
}

void write_particles(Hdf5Writer& h5, const std::vector<ParticleRecord>& p) {
  h5.write("particles/id", column<std::uint32_t>(p, [](const auto& r) { return r.id; }));
  h5.write("particles/species", column<std::int32_t>(p, [](const auto& r) { return r.species; }));
  h5.write("particles/shape", column<std::int32_t>(p, [](const auto& r) { return r.shape; }));
  h5.write("particles/fixed", column<std::int32_t>(p, [](const auto& r) { return r.fixed ? 1 : 0; }));
  h5.write("particles/mass", column<double>(p, [](const auto& r) { return r.mass; }));
  h5.write("particles/radius", column<double>(p, [](const auto& r) { return r.radius; }));
  h5.write("particles/volume", column<double>(p, [](const auto& r) { return r.volume; }));
  h5.write("particles/position", flat(column<Vec3>(p, [](const auto& r) { return r.position; })), 3);
  h5.write("particles/velocity", flat(column<Vec3>(p, [](const auto& r) { return r.velocity; })), 3);
  h5.write("particles/angular_velocity", flat(column<Vec3>(p, [](const auto& r) { return r.angular_velocity; })), 3);
  h5.write("particles/orientation", flat(column<Quat>(p, [](const auto& r) { return r.orientation; })), 4);
}

void write_contacts(Hdf5Writer& h5, const std::vector<ContactRecord>& c) {
  h5.write("contacts/i", column<std::int32_t>(c, [](const auto& r) { return r.i; }));
  h5.write("contacts/j", column<std::int32_t>(c, [](const auto& r) { return r.j; }));
  h5.write("contacts/wall", column<std::int32_t>(c, [](const auto& r) { return r.wall; }));
  h5.write("contacts/point", flat(column<Vec3>(c, [](const auto& r) { return r.point; })), 3);
  h5.write("contacts/normal", flat(column<Vec3>(c, [](const auto& r) { return r.normal; })), 3);
  h5.write("contacts/force", flat(column<Vec3>(c, [](const auto& r) { return r.force; })), 3);
  h5.write("contacts/overlap", column<double>(c, [](const auto& r) { return r.overlap; }));
}

// Every per-particle (or per-contact) dataset must have one row per record.
void expect_rows(const std::string& what, std::size_t rows, std::size_t expected) {
  if (rows != expected)
    throw std::runtime_error(what + " has " + std::to_string(rows) + " rows, expected " + std::to_string(expected));
}

std::vector<ParticleRecord> read_particles(const Hdf5Reader& h5) {
  const auto id = h5.read_u32("particles/id");
  const std::size_t n = id.size();
  const auto species = h5.read_i32("particles/species"), shape = h5.read_i32("particles/shape"),
             fixed = h5.read_i32("particles/fixed");
  const auto mass = h5.read_double("particles/mass"), radius = h5.read_double("particles/radius"),
             volume = h5.read_double("particles/volume");
  const auto position = vec3s(h5.read_double("particles/position", 3));
  const auto velocity = vec3s(h5.read_double("particles/velocity", 3));
  const auto angular = vec3s(h5.read_double("particles/angular_velocity", 3));
  const auto orientation = quats(h5.read_double("particles/orientation", 4));
  for (std::size_t rows : {species.size(), shape.size(), fixed.size(), mass.size(), radius.size(), volume.size(),
                           position.size(), velocity.size(), angular.size(), orientation.size()})
    expect_rows("a particle dataset", rows, n);
  std::vector<ParticleRecord> out(n);
  for (std::size_t k = 0; k < n; ++k)
    out[k] = {id[k], species[k], shape[k], fixed[k] != 0, mass[k], radius[k], volume[k],
              position[k], velocity[k], angular[k], orientation[k]};
  return out;
}

std::vector<ContactRecord> read_contacts(const Hdf5Reader& h5, std::size_t particles) {
  const auto i = h5.read_i32("contacts/i");
  const std::size_t n = i.size();
  const auto j = h5.read_i32("contacts/j"), wall = h5.read_i32("contacts/wall");
  const auto point = vec3s(h5.read_double("contacts/point", 3));
  const auto normal = vec3s(h5.read_double("contacts/normal", 3));
  const auto force = vec3s(h5.read_double("contacts/force", 3));
  const auto overlap = h5.read_double("contacts/overlap");
  for (std::size_t rows : {j.size(), wall.size(), point.size(), normal.size(), force.size(), overlap.size()})
    expect_rows("a contact dataset", rows, n);
  std::vector<ContactRecord> out(n);
  const auto np = static_cast<std::int32_t>(particles);
  for (std::size_t k = 0; k < n; ++k) {
    // Analyses index particles with these: an index outside the particle table is damage.
    if (i[k] < 0 || i[k] >= np || j[k] < -1 || j[k] >= np || (j[k] == -1 && wall[k] < 0))
      throw std::runtime_error("contact " + std::to_string(k) + " names a particle or wall that does not exist");
    out[k] = {i[k], j[k], wall[k], point[k], normal[k], force[k], overlap[k]};
  }
  return out;
}

}  // namespace

std::string snapshot_file_name(std::size_t index) {
  char name[32];
  std::snprintf(name, sizeof name, "snapshot_%06zu.h5", index);
  return name;
}

std::vector<std::filesystem::path> snapshot_files(const std::filesystem::path& results_dir) {
  std::vector<std::filesystem::path> files;
  const std::filesystem::path folder = results_dir / "snapshots";
  if (!std::filesystem::is_directory(folder)) return files;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file() && name.starts_with("snapshot_") && name.ends_with(".h5")) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());  // zero-padded numbers: name order is write order
  return files;
}

void write_snapshot_file(const std::filesystem::path& path, const Snapshot& s) {
  Hdf5Writer h5;
  h5.attribute("format", kFormat);
  h5.attribute("format_version", std::int64_t{kSnapshotFormatVersion});
  h5.attribute("talus_version", TALUS_VERSION);
  const std::vector<double> frame = {s.time,         s.gravity.x,    s.gravity.y,    s.gravity.z,
                                     s.domain_min.x, s.domain_min.y, s.domain_min.z, s.domain_max.x,
                                     s.domain_max.y, s.domain_max.z};
  h5.write("frame", frame);
  const std::vector<std::int32_t> periodic = {s.periodic[0], s.periodic[1], s.periodic[2]};
  h5.write("periodic", periodic);
  write_particles(h5, s.particles);
  write_contacts(h5, s.contacts);
  const std::vector<char> bytes = h5.image();
  atomic_write(path, std::string_view(bytes.data(), bytes.size()));
}

Snapshot read_snapshot_file(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path)) throw InputError(path.string() + ": no such file");
  std::optional<Hdf5Reader> file;
  try {
    file.emplace(path);
  } catch (const std::exception& e) {
    throw InputError(e.what());  // "PATH: not an HDF5 file"
  }
  const Hdf5Reader& h5 = *file;
  try {
    if (!h5.has_attribute("format") || h5.string_attribute("format") != kFormat)
      throw InputError(path.string() + ": not a Talus snapshot (no format = \"" + kFormat + "\" attribute)");
    const std::int64_t version = h5.int_attribute("format_version");
    if (version != kSnapshotFormatVersion)
      throw InputError(path.string() + ": snapshot format version " + std::to_string(version) + ", this talus reads " +
                       std::to_string(kSnapshotFormatVersion));
    Snapshot s;
    const std::vector<double> frame = h5.read_double("frame");
    expect_rows("frame", frame.size(), 10);
    s.time = frame[0];
    s.gravity = {frame[1], frame[2], frame[3]};
    s.domain_min = {frame[4], frame[5], frame[6]};
    s.domain_max = {frame[7], frame[8], frame[9]};
    const std::vector<std::int32_t> periodic = h5.read_i32("periodic");
    expect_rows("periodic", periodic.size(), 3);
    for (int a = 0; a < 3; ++a) s.periodic[a] = periodic[a] != 0;
    s.particles = read_particles(h5);
    s.contacts = read_contacts(h5, s.particles.size());
    return s;
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(path.string() + ": damaged snapshot: " + e.what());
  }
}

}  // namespace talus::io
