// Analyses of saved output: snapshot files keep every field an analysis reads, bit for bit, and
// coarse graining a run's saved snapshots gives what the live run computed (Weinhart et al.
// 2012, Sect. 3, "usable on a running simulation and on saved output").
#include <cmath>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "talus/io/hdf5_file.h"
#include "talus/io/input_error.h"
#include "talus/io/snapshot_file.h"
#include "talus/scenario/saved_coarse_grain.h"
#include "test_checkpoint_cases.h"

namespace talus {
namespace {

namespace fs = std::filesystem;

Snapshot varied_snapshot() {
  Snapshot s;
  s.time = 12.345678901234567;
  s.gravity = {0.40673664307580015, 0, -0.9135454576426009};
  s.domain_min = {0, 0, -2.5};
  s.domain_max = {20, 10, 1e300};
  s.periodic[0] = s.periodic[1] = true;
  for (int k = 0; k < 5; ++k) {
    ParticleRecord p;
    p.id = 7u * k + 3;
    p.species = k % 2;
    p.shape = k == 4 ? 2 : 0;
    p.fixed = k == 0;
    p.mass = 1.0 / (k + 3);
    p.radius = 0.5 + 1e-17 * k;
    p.volume = M_PI / 6 * (k + 1);
    p.position = {0.1 * k, std::sqrt(k + 0.5), -1.0 / 3 * k};
    p.velocity = {1e-300 * k, -2.0 * k, 1.0 / 7};
    p.angular_velocity = {k * 1e10, 0.25, -k * 0.125};
    p.orientation = Quat{0.5, -0.5, 0.5, 0.5};
    s.particles.push_back(p);
  }
  s.contacts.push_back({1, 2, -1, {0.15, 1.1, -0.5}, {1, 0, 0}, {-3.5, 1e-3, 2.25}, 1e-4});
  s.contacts.push_back({3, -1, 0, {0.3, 1.9, -2.5}, {0, 0, 1}, {0, 0, 9.81}, 3e-6});
  return s;
}

std::string read_error(const fs::path& path) {
  try {
    io::read_snapshot_file(path);
  } catch (const io::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SnapshotFile, RoundTripsEveryFieldBitForBit) {
  const fs::path dir = testing::test_folder();
  const Snapshot s = varied_snapshot();
  io::write_snapshot_file(dir / io::snapshot_file_name(3), s);
  EXPECT_EQ(io::snapshot_files(dir).size(), 0u);  // only DIR/snapshots/ holds a run's files
  const Snapshot r = io::read_snapshot_file(dir / "snapshot_000003.h5");
  EXPECT_EQ(r.time, s.time);
  EXPECT_EQ(r.gravity, s.gravity);
  EXPECT_EQ(r.domain_min, s.domain_min);
  EXPECT_EQ(r.domain_max, s.domain_max);
  for (int a = 0; a < 3; ++a) EXPECT_EQ(r.periodic[a], s.periodic[a]);
  ASSERT_EQ(r.particles.size(), s.particles.size());
  for (std::size_t k = 0; k < s.particles.size(); ++k) {
    const ParticleRecord &a = r.particles[k], &b = s.particles[k];
    EXPECT_EQ(a.id, b.id);
    EXPECT_EQ(a.species, b.species);
    EXPECT_EQ(a.shape, b.shape);
    EXPECT_EQ(a.fixed, b.fixed);
    EXPECT_EQ(a.mass, b.mass);
    EXPECT_EQ(a.radius, b.radius);
    EXPECT_EQ(a.volume, b.volume);
    EXPECT_EQ(a.position, b.position);
    EXPECT_EQ(a.velocity, b.velocity);
    EXPECT_EQ(a.angular_velocity, b.angular_velocity);
    EXPECT_EQ(a.orientation.w, b.orientation.w);
    EXPECT_EQ(a.orientation.x, b.orientation.x);
    EXPECT_EQ(a.orientation.y, b.orientation.y);
    EXPECT_EQ(a.orientation.z, b.orientation.z);
  }
  ASSERT_EQ(r.contacts.size(), s.contacts.size());
  for (std::size_t k = 0; k < s.contacts.size(); ++k) {
    const ContactRecord &a = r.contacts[k], &b = s.contacts[k];
    EXPECT_EQ(a.i, b.i);
    EXPECT_EQ(a.j, b.j);
    EXPECT_EQ(a.wall, b.wall);
    EXPECT_EQ(a.point, b.point);
    EXPECT_EQ(a.normal, b.normal);
    EXPECT_EQ(a.force, b.force);
    EXPECT_EQ(a.overlap, b.overlap);
  }
  // An empty system (no contacts yet) round-trips too.
  Snapshot empty;
  io::write_snapshot_file(dir / "empty.h5", empty);
  EXPECT_TRUE(io::read_snapshot_file(dir / "empty.h5").particles.empty());
  fs::remove_all(dir);
}

TEST(SnapshotFile, MissingForeignOrDamagedFilesAreNamed) {
  const fs::path dir = testing::test_folder();
  EXPECT_EQ(read_error(dir / "none.h5"), (dir / "none.h5").string() + ": no such file");
  std::ofstream(dir / "text.h5") << "not a snapshot\n";
  EXPECT_EQ(read_error(dir / "text.h5"), (dir / "text.h5").string() + ": not an HDF5 file");
  auto save = [](const fs::path& p, const std::vector<char>& b) {
    std::ofstream(p, std::ios::binary).write(b.data(), static_cast<std::streamsize>(b.size()));
  };
  {
    io::Hdf5Writer h5;
    h5.write("data", std::vector<double>{1, 2, 3});
    save(dir / "other.h5", h5.image());
  }
  EXPECT_EQ(read_error(dir / "other.h5"),
            (dir / "other.h5").string() + ": not a Talus snapshot (no format = \"talus-snapshot\" attribute)");
  // One flipped bit in a contact force: the dataset's checksum no longer matches.
  io::write_snapshot_file(dir / "good.h5", varied_snapshot());
  std::ifstream in(dir / "good.h5", std::ios::binary);
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const double force_x = -3.5;
  auto it = std::search(bytes.begin(), bytes.end(), reinterpret_cast<const char*>(&force_x),
                        reinterpret_cast<const char*>(&force_x + 1));
  ASSERT_NE(it, bytes.end());
  bytes[static_cast<std::size_t>(it - bytes.begin()) + 2] ^= 0x04;
  save(dir / "flipped.h5", bytes);
  const std::string flipped = read_error(dir / "flipped.h5");
  EXPECT_EQ(flipped.rfind((dir / "flipped.h5").string() + ": damaged snapshot", 0), 0u) << flipped;
  fs::remove_all(dir);
}

std::string grid_error(const std::vector<std::string>& axes) {
  try {
    parse_cg_grid(axes);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(SavedCoarseGraining, GridSpecificationsAreReadOrRefusedByName) {
  const CgGrid depth = parse_cg_grid({"z=-1.5:40:200"});
  EXPECT_EQ(depth.dim(), 1);
  EXPECT_TRUE(depth.resolved[2]);
  EXPECT_EQ(depth.n[2], 200);
  EXPECT_EQ(depth.lo[2], -1.5);
  EXPECT_EQ(depth.hi[2], 40);
  const CgGrid volume = parse_cg_grid({"x=0:19.5:40", "y=0:9.5:20", "z=0:39:40"});
  EXPECT_EQ(volume.dim(), 3);
  EXPECT_EQ(volume.size(), 40 * 20 * 40);
  EXPECT_EQ(grid_error({}), "grid: name at least one axis, e.g. z=0:40:200");
  EXPECT_EQ(grid_error({"z=0:40"}), "grid \"z=0:40\": expected AXIS=LO:HI:N, e.g. z=0:40:200");
  EXPECT_EQ(grid_error({"w=0:1:3"}), "grid \"w=0:1:3\": the axis is x, y or z");
  EXPECT_EQ(grid_error({"z=0:one:3"}), "grid \"z=0:one:3\": \"one\" is not a number");
  EXPECT_EQ(grid_error({"z=0:1:2.5"}), "grid \"z=0:1:2.5\": N must be a whole number >= 1");
  EXPECT_EQ(grid_error({"z=0:1:3", "z=0:2:3"}), "grid \"z=0:2:3\": axis z given twice");
  EXPECT_EQ(grid_error({"z=2:1:3"}).rfind("grid \"z=2:1:3\": CgGrid", 0), 0u);
}

// A small chute (10 x 5, H = 4, theta = 24 deg) whose live depth profiles sample the same
// instants as its snapshot files: one per time unit over [2, 6].
constexpr char kSmallChute[] = R"(
[run]
end_time = 6.0
output_interval = 0.5
seed = 5
snapshot_interval = 1.0

[chute]
length = 10.0
width = 5.0
base_diameter = 1.0
fill_height = 4.0
angle = 24.0

[chute.coarse_graining]
start = 2.0
interval = 1.0
width = 0.25
z_max = 8.0

[contact]
model = "elastic_spring"
normal_stiffness = 2e5
normal_damping_rate = 50
tangential_stiffness_ratio = 0.2857142857142857
tangential_damping_rate = 50
friction = 0.5
)";

std::string file_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// What `talus analyze DIR --set ...` does: the folder's scenario plus overrides, re-measured.
nlohmann::json reanalyse(const fs::path& dir, const std::vector<std::string>& overrides) {
  io::ScenarioFile f = io::ScenarioFile::from_file(dir / "scenario.toml");
  for (const auto& o : overrides) f.set_override(o);
  Scenario sc = load_scenario(f);
  std::ifstream in(dir / "summary.json");
  nlohmann::json summary = nlohmann::json::parse(in);
  bool any = false;
  for (auto& o : sc.observers) any = o->reanalyse(dir, summary) || any;
  EXPECT_TRUE(any);
  return summary;
}

// ∫ rho dz of a depth profile by the trapezoid rule (columns z and density).
double column_mass(const CgFields& f) {
  double mass = 0;
  for (int k = 0; k + 1 < f.grid.size(); ++k)
    mass += 0.5 * (f.values[k].density + f.values[k + 1].density) * f.grid.spacing(2);
  return mass;
}

// ∫ rho dz of a chute_profile.csv by the trapezoid rule.
double profile_mass(const fs::path& csv_path) {
  std::ifstream csv(csv_path);
  std::string line, cell;
  std::getline(csv, line);
  int z = -1, rho = -1, col = 0;
  for (std::stringstream head(line); std::getline(head, cell, ','); ++col) {
    if (cell == "z") z = col;
    if (cell == "density") rho = col;
  }
  EXPECT_GE(z, 0);
  EXPECT_GE(rho, 0);
  std::vector<std::pair<double, double>> rows;
  while (std::getline(csv, line)) {
    std::vector<double> row;
    for (std::stringstream s(line); std::getline(s, cell, ',');) row.push_back(std::stod(cell));
    rows.emplace_back(row.at(z), row.at(rho));
  }
  double mass = 0;
  for (std::size_t k = 0; k + 1 < rows.size(); ++k)
    mass += 0.5 * (rows[k].second + rows[k + 1].second) * (rows[k + 1].first - rows[k].first);
  return mass;
}

TEST(SavedCoarseGraining, SavedSnapshotsGiveTheLiveProfilesAndAnyOtherGrid) {
  const fs::path dir = testing::test_folder();
  io::ScenarioFile f = io::ScenarioFile::from_string(kSmallChute, "small_chute.toml");
  Scenario sc = load_scenario(f);
  RunOptions opt;
  opt.out = dir;
  opt.overwrite = true;
  opt.quiet = true;
  opt.scenario_toml = f.to_toml();
  run_scenario(sc, opt);
  ASSERT_EQ(io::snapshot_files(dir).size(), 7u);  // t = 0, 1, ..., 6
  const std::string live_profile = file_text(dir / "chute_profile.csv");
  std::ifstream in(dir / "summary.json");
  const nlohmann::json live = nlohmann::json::parse(in);

  // Same instants, same function: the same profile to the last bit, and the same closures.
  const nlohmann::json again = reanalyse(dir, {});
  EXPECT_EQ(file_text(dir / "chute_profile.csv"), live_profile);
  for (const char* key : {"flow_state", "h", "base", "surface", "mean_velocity", "froude", "mu_macro", "K", "alpha",
                          "bulk_volume_fraction"})
    EXPECT_EQ(again[key], live[key]) << key;
  EXPECT_EQ(again["chute"]["checks"], live["chute"]["checks"]);
  EXPECT_EQ(again["chute"]["snapshots"].get<int>(), 5);

  // Another width from the same files: a new profile, which still holds the flowing mass.
  const nlohmann::json wide = reanalyse(dir, {"chute.coarse_graining.width=1.0", "chute.coarse_graining.z_max=14"});
  EXPECT_NE(file_text(dir / "chute_profile.csv"), live_profile);
  EXPECT_EQ(wide["chute"]["width"].get<double>(), 1.0);
  const double mass_per_area = live["chute"]["flowing_mass_per_area"].get<double>();
  EXPECT_NEAR(profile_mass(dir / "chute_profile.csv"), mass_per_area, 1e-5 * mass_per_area);

  // Any grid through coarse_grain_saved. Depth profile over the window: the cut Gaussian
  // integrates to one, and the trapezoid rule on w/4 spacing is exact to ~1e-6 (its jump at
  // the cutoff).
  const SavedCoarseGraining depth =
      coarse_grain_saved(dir, parse_cg_grid({"z=-4:12:257"}), CgFunction::gaussian(0.25, 1), 2.0, 6.5);
  EXPECT_EQ(depth.snapshots, 5);
  EXPECT_NEAR(column_mass(depth.mean), mass_per_area, 1e-5 * mass_per_area);
  // A 3D grid on one snapshot: along the periodic x and y a regular grid sums a smooth function
  // spectrally accurately, so the grid sum times the cell volume is the flowing mass. The cutoff
  // goes to 5 w, where the jump of the cut Gaussian (4e-6 of its peak) no longer shows.
  const CgGrid volume = parse_cg_grid({"x=0:9.75:40", "y=0:4.75:20", "z=-4:12:129"});
  const SavedCoarseGraining field = coarse_grain_saved(dir, volume, CgFunction::gaussian(0.5, 3, 2.5), 6.0, 6.5);
  EXPECT_EQ(field.snapshots, 1);
  double sum = 0;
  for (int k = 0; k < volume.size(); ++k) {
    const int iz = k / (40 * 20);
    sum += (iz == 0 || iz == 128 ? 0.5 : 1.0) * field.mean.values[k].density;
  }
  const double cell = volume.spacing(0) * volume.spacing(1) * volume.spacing(2);
  EXPECT_NEAR(sum * cell, mass_per_area * 50, 1e-5 * mass_per_area * 50);
  // The CSV names its columns and has one row per grid point.
  write_cg_fields_csv(dir / "field.csv", field.mean);
  std::ifstream csv(dir / "field.csv");
  std::string header, line;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("x,y,z,density,momentum_x", 0), 0u) << header;
  int rows = 0;
  while (std::getline(csv, line)) ++rows;
  EXPECT_EQ(rows, volume.size());
  // A window with no snapshot is an error, not an empty field.
  EXPECT_THROW(coarse_grain_saved(dir, volume, CgFunction::gaussian(0.5, 3), 100, 200), std::runtime_error);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace talus
