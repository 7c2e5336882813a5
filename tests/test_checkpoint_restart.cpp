// A run restarted from a checkpoint follows the uninterrupted run bit for bit: positions,
// velocities, orientations, angular velocities, forces and every contact memory, for spheres
// with the memory model in a box, a periodic chute with the elastic_spring model, and crosses
// with contact manifolds while a pour is in progress. And writing checkpoints does not change
// a run at all.
#include <gtest/gtest.h>

#include <fstream>
#include <limits>
#include <sstream>

#include "talus/io/input_error.h"
#include "talus/scenario/checkpoint_series.h"
#include "test_checkpoint_cases.h"

namespace talus {
namespace {

namespace fs = std::filesystem;
using testing::expect_same_state;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs `toml` with checkpoints every `interval` (run A), restarts from the first checkpoint
// into another folder (run B) and compares the two final checkpoints and time series.
// Returns the checkpoint B started from.
io::Checkpoint expect_exact_restart(const std::string& toml, double interval) {
  const fs::path dir = testing::test_folder();
  testing::run_case(toml, dir / "a", interval);
  const std::vector<fs::path> written = CheckpointSeries::list(dir / "a" / "checkpoints");
  EXPECT_GE(written.size(), 2u);
  auto middle = std::make_shared<io::Checkpoint>(io::read_checkpoint(written.front()));
  testing::run_case(toml, dir / "b", 0, middle, written.front().string());

  const io::Checkpoint a = io::read_checkpoint(CheckpointSeries::latest(dir / "a"));
  const io::Checkpoint b = io::read_checkpoint(CheckpointSeries::latest(dir / "b"));
  EXPECT_GT(a.world.steps, middle->world.steps);
  expect_same_state(a.world, b.world);
  EXPECT_EQ(slurp(dir / "a" / "timeseries.csv"), slurp(dir / "b" / "timeseries.csv"));
  fs::remove_all(dir);
  return *middle;
}

TEST(CheckpointRestart, SettlingBoxWithMemoryModelIsBitForBit) {
  const io::Checkpoint middle = expect_exact_restart(testing::kSettlingBox, 0.06);
  // The restart had history to carry: tangential and rolling springs, particle pairs and walls.
  EXPECT_GT(testing::live_springs(middle.world.pair_memory), 20u);
  EXPECT_GT(testing::live_springs(middle.world.wall_memory), 5u);
  std::size_t rolling = 0;
  for (const Vec3& m : middle.world.pair_memory.rolling) rolling += norm2(m) > 0;
  EXPECT_GT(rolling, 0u);
}

TEST(CheckpointRestart, PeriodicChuteWithElasticSpringIsBitForBit) {
  const io::Checkpoint middle = expect_exact_restart(testing::kChute, 4.0);
  EXPECT_GT(testing::live_springs(middle.world.pair_memory), 5u);
  // Pairs across the periodic boundary carry memory too: some particle sits within a diameter
  // of the x faces (the chute spans x in [0, 6]).
  std::size_t near_face = 0;
  for (const Vec3& x : middle.world.particles.position) near_face += x.x < 1 || x.x > 5;
  EXPECT_GT(near_face, 0u);
}

TEST(CheckpointRestart, PouringCrossesWithManifoldsAreBitForBit) {
  const io::Checkpoint middle = expect_exact_restart(testing::kCrossPour, 0.08);
  // Contact points of crosses with their own memory, between crosses and with the floor.
  EXPECT_GT(testing::live_point_springs(middle.world.pair_sub), 0u);
  EXPECT_GT(testing::live_point_springs(middle.world.wall_sub), 0u);
  // The pour was half way: its random generator and counters crossed the restart.
  const auto& pour = middle.run.at("pours").at(0);
  EXPECT_GT(pour.at("poured").get<std::size_t>(), 0u);
  EXPECT_LT(pour.at("poured").get<std::size_t>(), 8u);
}

// Counts the steps it sees; the count crosses a restart only through state() and restore().
class StepCounter : public RunObserver {
 public:
  std::string name() const override { return "step_counter"; }
  void after_step(World& /*world*/) override { ++steps_; }
  // Called at every step, not at the end of batches only.
  double next_step_event(const World& /*world*/) const override { return -std::numeric_limits<double>::infinity(); }
  void finish(World& /*world*/, const fs::path& /*out*/, nlohmann::json& summary) override {
    summary["observed_steps"] = steps_;
  }
  nlohmann::json state() const override { return {{"steps", steps_}}; }
  void restore(const nlohmann::json& state) override { steps_ = state.at("steps").get<std::uint64_t>(); }

 private:
  std::uint64_t steps_ = 0;
};

TEST(CheckpointRestart, ObserverStateCrossesTheRestart) {
  const fs::path dir = testing::test_folder();
  auto with_counter = [](Scenario& sc) { sc.observers.push_back(std::make_unique<StepCounter>()); };
  testing::run_case(testing::kSettlingBox, dir / "a", 0.06, nullptr, "", with_counter);
  const fs::path middle = CheckpointSeries::list(dir / "a" / "checkpoints").front();
  auto checkpoint = std::make_shared<io::Checkpoint>(io::read_checkpoint(middle));
  EXPECT_EQ(checkpoint->run.at("observers").at(0).at("state").at("steps"), checkpoint->world.steps);
  testing::run_case(testing::kSettlingBox, dir / "b", 0, checkpoint, middle.string(), with_counter);
  const nlohmann::json summary = nlohmann::json::parse(slurp(dir / "b" / "summary.json"));
  EXPECT_EQ(summary.at("observed_steps"), summary.at("steps"));
  EXPECT_GT(summary.at("steps").get<std::uint64_t>(), checkpoint->world.steps);

  // A scenario without the observer cannot take the checkpoint over.
  try {
    testing::run_case(testing::kSettlingBox, dir / "c", 0, checkpoint, "mid.h5");
    ADD_FAILURE() << "restart without the observer was accepted";
  } catch (const io::InputError& e) {
    EXPECT_STREQ(e.what(), "mid.h5: checkpoint's run observers differ from the scenario's");
  }
  fs::remove_all(dir);
}

TEST(CheckpointRestart, CheckpointsDoNotChangeTheRun) {
  // A checkpoint leaves the World untouched, so a run with checkpoints every few steps ends
  // exactly where a run without them does.
  const fs::path dir = testing::test_folder();
  testing::run_case(testing::kSettlingBox, dir / "often", 0.01);
  testing::run_case(testing::kSettlingBox, dir / "once", 0);
  const io::Checkpoint often = io::read_checkpoint(CheckpointSeries::latest(dir / "often"));
  const io::Checkpoint once = io::read_checkpoint(CheckpointSeries::latest(dir / "once"));
  EXPECT_EQ(CheckpointSeries::list(dir / "often" / "checkpoints").size(), 3u);  // the last three kept
  expect_same_state(often.world, once.world);
  fs::remove_all(dir);
}

TEST(CheckpointRestart, ResumedRunKeepsTheCadenceItWasStartedWith) {
  // The interval came from the command line (RunOptions), not the scenario; the run resumed
  // without it writes its checkpoints at the same steps as the uninterrupted run, not one at
  // every batch once the next was due.
  const fs::path dir = testing::test_folder();
  testing::run_case(testing::kSettlingBox, dir / "a", 0.01);
  const std::vector<fs::path> a = CheckpointSeries::list(dir / "a" / "checkpoints");
  ASSERT_EQ(a.size(), 3u);
  auto first = std::make_shared<io::Checkpoint>(io::read_checkpoint(a.front()));
  testing::run_case(testing::kSettlingBox, dir / "b", 0, first, a.front().string());
  const std::vector<fs::path> b = CheckpointSeries::list(dir / "b" / "checkpoints");
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b[0].filename(), a[1].filename());
  EXPECT_EQ(b[1].filename(), a[2].filename());
  fs::remove_all(dir);
}

}  // namespace
}  // namespace talus
