// Checkpoint files: a World state survives the file bit for bit, and a file that is not a
// checkpoint, is damaged, or has another format version gives a one-line error naming it.
#include <gtest/gtest.h>

#include <fstream>
#include <limits>

#include "talus/io/checkpoint_file.h"
#include "talus/io/hdf5_file.h"
#include "talus/io/input_error.h"
#include "test_checkpoint_cases.h"

namespace talus {
namespace {

namespace fs = std::filesystem;

// A checkpoint of a box of spheres after some settling, taken straight from the World.
io::Checkpoint settled_box_checkpoint() {
  io::ScenarioFile file = io::ScenarioFile::from_string(testing::kSettlingBox, "case.toml");
  Scenario scenario = load_scenario(file);
  scenario.world->run(6000);
  io::Checkpoint c;
  c.scenario_toml = file.to_toml();
  c.world = scenario.world->capture_state();
  c.timeseries_columns = {"time", "step"};
  c.timeseries = {0.0, 0.0, 0.5, 1.0};
  c.run = {{"next_output", 0.1}};
  return c;
}

// The error message read_checkpoint gives for `path`, or "" if it loads.
std::string load_error(const fs::path& path) {
  try {
    io::read_checkpoint(path);
  } catch (const io::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CheckpointFile, WorldStateRoundTripsBitForBit) {
  const fs::path dir = testing::test_folder();
  io::Checkpoint c = settled_box_checkpoint();
  c.world.walls[1].motion.kind = WallMotion::Kind::accelerated;  // motions and odd numbers survive too
  c.world.walls[1].motion.acceleration = 43.0 / 3.0;
  c.world.walls[1].motion.start_time = 0.1;
  c.world.walls[2].motion.kind = WallMotion::Kind::accelerated;  // a gate not opened yet starts at +inf
  c.world.walls[2].motion.start_time = std::numeric_limits<double>::infinity();
  io::write_checkpoint(dir / "c.h5", c);
  const io::Checkpoint back = io::read_checkpoint(dir / "c.h5");
  EXPECT_GT(testing::live_springs(c.world.pair_memory), 0u);
  testing::expect_same_state(c.world, back.world);
  EXPECT_TRUE(testing::same_bits(c.world.particles.radius, back.world.particles.radius));
  EXPECT_TRUE(testing::same_bits(c.world.particles.inv_inertia, back.world.particles.inv_inertia));
  EXPECT_EQ(c.world.skin, back.world.skin);
  EXPECT_EQ(c.world.time_at_build, back.world.time_at_build);
  ASSERT_EQ(back.world.walls.size(), c.world.walls.size());
  EXPECT_EQ(back.world.walls[1].motion.acceleration, 43.0 / 3.0);
  EXPECT_EQ(back.world.walls[1].motion.kind, WallMotion::Kind::accelerated);
  EXPECT_EQ(back.world.walls[2].motion.start_time, std::numeric_limits<double>::infinity());
  EXPECT_EQ(back.world.walls[4].name, "floor");
  EXPECT_EQ(back.scenario_toml, c.scenario_toml);
  EXPECT_EQ(back.timeseries, c.timeseries);
  EXPECT_EQ(back.run, c.run);
  EXPECT_EQ(back.talus_version, TALUS_VERSION);
  fs::remove_all(dir);
}

// A state gathered from ranks keeps their layout (the grid's cuts and each rank's share), so
// that a restart on as many ranks can hand every rank its share back; shares that do not add up
// are refused.
TEST(CheckpointFile, RankLayoutRoundTripsAndMustAddUp) {
  const fs::path dir = testing::test_folder();
  io::Checkpoint c = settled_box_checkpoint();
  WorldState& w = c.world;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  w.ranks = 6;  // 3 x 1 x 2
  w.layout.axis = 2;
  w.layout.rebalance = true;
  w.layout.min_width = 2.6e-3;
  w.layout.cut[0] = {-kInf, 0.004, 0.01, kInf};
  w.layout.cut[2] = {-kInf, 0.0123, kInf};
  const std::uint64_t n = w.particles.owned, pairs = w.pair_gid_i.size(), walls = w.wall_gid.size();
  w.layout.particles = {n / 3, n / 3, 0, 0, 0, n - 2 * (n / 3)};
  w.layout.pair_entries = {pairs / 2, 0, 0, 0, 0, pairs - pairs / 2};
  w.layout.wall_entries = {walls, 0, 0, 0, 0, 0};
  io::write_checkpoint(dir / "c.h5", c);
  const WorldState back = io::read_checkpoint(dir / "c.h5").world;
  EXPECT_TRUE(back.fits_ranks(6));
  EXPECT_FALSE(back.fits_ranks(2));
  EXPECT_EQ(back.layout.axis, 2);
  EXPECT_TRUE(back.layout.rebalance);
  EXPECT_EQ(back.layout.min_width, 2.6e-3);
  EXPECT_EQ(back.layout.cut, w.layout.cut);
  EXPECT_EQ(back.layout.particles, w.layout.particles);
  EXPECT_EQ(back.layout.pair_entries, w.layout.pair_entries);
  EXPECT_EQ(back.layout.wall_entries, w.layout.wall_entries);

  w.layout.particles[1] += 1;
  io::write_checkpoint(dir / "bad.h5", c);
  EXPECT_EQ(load_error(dir / "bad.h5"), (dir / "bad.h5").string() +
                                            ": rank layout does not add up to the stored arrays");
  fs::remove_all(dir);
}

TEST(CheckpointFile, RestoredWorldStepsOnBitForBit) {
  io::ScenarioFile file = io::ScenarioFile::from_string(testing::kSettlingBox, "case.toml");
  Scenario original = load_scenario(file);
  original.world->run(6000);
  const WorldState middle = original.world->capture_state();
  io::ScenarioFile again = io::ScenarioFile::from_string(testing::kSettlingBox, "case.toml");
  Scenario restored = load_scenario(again);
  restored.world->restore_state(middle);
  original.world->run(700);
  restored.world->run(700);
  testing::expect_same_state(original.world->capture_state(), restored.world->capture_state());
}

TEST(CheckpointFile, MissingOrForeignFilesAreNamed) {
  const fs::path dir = testing::test_folder();
  EXPECT_EQ(load_error(dir / "none.h5"), (dir / "none.h5").string() + ": no such file");
  std::ofstream(dir / "text.h5") << "not a checkpoint\n";
  EXPECT_EQ(load_error(dir / "text.h5"), (dir / "text.h5").string() + ": not an HDF5 file");
  {
    io::Hdf5Writer h5;  // an HDF5 file of something else
    h5.write("data", std::vector<double>{1, 2, 3});
    const std::vector<char> bytes = h5.image();
    std::ofstream(dir / "other.h5", std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  }
  EXPECT_EQ(load_error(dir / "other.h5"),
            (dir / "other.h5").string() + ": not a Talus checkpoint (no format = \"talus-checkpoint\" attribute)");
  fs::remove_all(dir);
}

TEST(CheckpointFile, AnotherFormatVersionIsRefused) {
  const fs::path dir = testing::test_folder();
  io::Hdf5Writer h5;
  h5.attribute("format", "talus-checkpoint");
  h5.attribute("format_version", std::int64_t{io::kCheckpointFormatVersion + 1});
  h5.attribute("talus_version", "9.9.9");
  const std::vector<char> bytes = h5.image();
  std::ofstream(dir / "future.h5", std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  EXPECT_EQ(load_error(dir / "future.h5"), (dir / "future.h5").string() + ": checkpoint format version " +
                                               std::to_string(io::kCheckpointFormatVersion + 1) +
                                               " (written by talus 9.9.9); this talus (" + TALUS_VERSION +
                                               ") reads version " + std::to_string(io::kCheckpointFormatVersion));
  fs::remove_all(dir);
}

TEST(CheckpointFile, TruncatedOrDamagedFilesAreRefused) {
  const fs::path dir = testing::test_folder();
  const io::Checkpoint c = settled_box_checkpoint();
  const std::vector<char> bytes = io::checkpoint_image(c);
  auto save = [&](const fs::path& p, const std::vector<char>& b) {
    std::ofstream(p, std::ios::binary).write(b.data(), static_cast<std::streamsize>(b.size()));
  };
  // Cut short, as a copy interrupted half way would be.
  save(dir / "short.h5", std::vector<char>(bytes.begin(), bytes.begin() + bytes.size() / 2));
  const std::string cut = load_error(dir / "short.h5");
  EXPECT_EQ(cut.rfind((dir / "short.h5").string() + ": ", 0), 0u) << cut;
  EXPECT_EQ(cut.find('\n'), std::string::npos);

  // One flipped bit in the particle velocities: the dataset's checksum no longer matches.
  const std::vector<double> v = {c.world.particles.velocity[7].x, c.world.particles.velocity[7].y,
                                 c.world.particles.velocity[7].z};
  auto it = std::search(bytes.begin(), bytes.end(), reinterpret_cast<const char*>(v.data()),
                        reinterpret_cast<const char*>(v.data() + 3));
  ASSERT_NE(it, bytes.end());
  std::vector<char> flipped = bytes;
  flipped[static_cast<std::size_t>(it - bytes.begin()) + 3] ^= 0x10;
  save(dir / "flipped.h5", flipped);
  EXPECT_EQ(load_error(dir / "flipped.h5"), (dir / "flipped.h5").string() +
                                                ": dataset world/particles/velocity does not match its checksum (corrupt file)");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace talus
