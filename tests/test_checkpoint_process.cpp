// Checkpoints under real signals, with the talus command itself:
// - SIGKILL at any moment, even while a checkpoint is being written, leaves only complete
//   checkpoints under checkpoint names (and latest.h5 naming one of them);
// - SIGTERM ends the run at the end of a step with its results and a final checkpoint, and
//   `talus resume` then ends exactly where the uninterrupted run ends, bit for bit.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>

#include "talus/io/input_error.h"
#include "talus/scenario/checkpoint_series.h"
#include "test_checkpoint_cases.h"

namespace talus {
namespace {

namespace fs = std::filesystem;

const std::string kTalus = std::string(TALUS_BINARY_DIR) + "/talus";

// Starts `talus ARGS...` with its output discarded.
pid_t spawn_talus(std::vector<std::string> args) {
  args.insert(args.begin(), kTalus);
  const pid_t pid = fork();
  if (pid == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    dup2(null, STDOUT_FILENO);
    dup2(null, STDERR_FILENO);
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  return pid;
}

// Exit status of a process that exited, or 128 + signal of one that was killed.
int wait_for(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string with_end_time(const std::string& toml, const std::string& end_time) {
  const std::string key = "end_time = ";
  const std::size_t at = toml.find(key) + key.size();
  return toml.substr(0, at) + end_time + toml.substr(toml.find('\n', at));
}

TEST(CheckpointProcess, KilledAtAnyMomentLeavesOnlyCompleteCheckpoints) {
  const fs::path dir = testing::test_folder();
  // A checkpoint at every step: most of the run's time is spent writing them.
  std::ofstream(dir / "case.toml") << with_end_time(testing::kSettlingBox, "10.0") << "\n";
  std::size_t complete = 0, partial = 0;
  for (int k = 0; k < 6; ++k) {
    const pid_t pid = spawn_talus({"run", (dir / "case.toml").string(), "--out", (dir / "out").string(), "--overwrite",
                                   "--quiet", "--threads", "1", "--checkpoint-interval", "1e-9"});
    std::this_thread::sleep_for(std::chrono::milliseconds(400 + 137 * k));
    kill(pid, SIGKILL);
    ASSERT_EQ(wait_for(pid), 128 + SIGKILL);

    const fs::path checkpoints = dir / "out" / "checkpoints";
    const std::vector<fs::path> listed = CheckpointSeries::list(checkpoints);
    ASSERT_FALSE(listed.empty()) << "kill " << k << " came before the first checkpoint";
    for (const fs::path& p : listed) {
      const io::Checkpoint c = io::read_checkpoint(p);  // throws on a damaged file
      EXPECT_EQ(p.filename().string(), CheckpointSeries::file_name(c.world.steps));
      EXPECT_EQ(c.world.particles.owned, 60u);
      ++complete;
    }
    for (const fs::directory_entry& e : fs::directory_iterator(checkpoints)) {
      const std::string name = e.path().filename().string();
      if (name.find(".tmp.") != std::string::npos) {
        ++partial;  // a checkpoint cut off mid-write: never under a checkpoint name
        EXPECT_EQ(std::count(listed.begin(), listed.end(), e.path()), 0);
      }
    }
    const fs::path latest = CheckpointSeries::latest(dir / "out");
    ASSERT_TRUE(fs::exists(latest));
    EXPECT_NO_THROW(io::read_checkpoint(latest));
    EXPECT_EQ(std::count(listed.begin(), listed.end(), checkpoints / fs::read_symlink(latest)), 1);
  }
  std::cout << "[ checkpoints ] " << complete << " complete checkpoints checked; " << partial
            << " kills landed while a checkpoint was being written\n";
  fs::remove_all(dir);
}

TEST(CheckpointProcess, TerminatedRunResumesToTheSameEnd) {
  const fs::path dir = testing::test_folder();
  std::string toml = with_end_time(testing::kSettlingBox, "0.2");
  toml.insert(toml.find("[domain]"), "checkpoint_interval = 0.01\n");
  std::ofstream(dir / "case.toml") << toml;

  const pid_t reference = spawn_talus({"run", (dir / "case.toml").string(), "--out", (dir / "ref").string(), "--quiet"});
  ASSERT_EQ(wait_for(reference), 0);

  const pid_t pid = spawn_talus({"run", (dir / "case.toml").string(), "--out", (dir / "cut").string(), "--quiet"});
  const fs::path first = dir / "cut" / "checkpoints" / "latest.h5";
  for (int wait = 0; wait < 3000 && !fs::exists(first); ++wait) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  kill(pid, SIGTERM);  // a few steps after the first checkpoint, long before the end
  ASSERT_EQ(wait_for(pid), 130) << "the run should stop on SIGTERM with exit status 130";

  // The interrupted folder is complete: summary, time series, a final checkpoint.
  const nlohmann::json summary = nlohmann::json::parse(slurp(dir / "cut" / "summary.json"));
  EXPECT_EQ(summary.at("stop_reason"), "interrupted");
  EXPECT_TRUE(fs::exists(dir / "cut" / "timeseries.csv"));
  const io::Checkpoint last = io::read_checkpoint(CheckpointSeries::latest(dir / "cut"));
  EXPECT_EQ(last.world.steps, summary.at("steps").get<std::uint64_t>());
  const io::Checkpoint end = io::read_checkpoint(CheckpointSeries::latest(dir / "ref"));
  ASSERT_LT(last.world.steps, end.world.steps) << "SIGTERM came after the run had ended";

  const pid_t resumed = spawn_talus({"resume", (dir / "cut").string(), "--quiet"});
  ASSERT_EQ(wait_for(resumed), 0);
  testing::expect_same_state(io::read_checkpoint(CheckpointSeries::latest(dir / "cut")).world, end.world);
  EXPECT_EQ(slurp(dir / "cut" / "timeseries.csv"), slurp(dir / "ref" / "timeseries.csv"));
  const nlohmann::json resumed_summary = nlohmann::json::parse(slurp(dir / "cut" / "summary.json"));
  EXPECT_EQ(resumed_summary.at("stop_reason"), "end_time");
  EXPECT_EQ(resumed_summary.at("restarted_from").at("step").get<std::uint64_t>(), last.world.steps);
  fs::remove_all(dir);
}

// A restart may write into a new folder; its VTK series starts there, with no earlier frames.
TEST(CheckpointProcess, RestartIntoANewFolderWritesItsVtkSeries) {
  const fs::path dir = testing::test_folder();
  std::string toml = with_end_time(testing::kSettlingBox, "0.04");
  toml.insert(toml.find("[domain]"), "checkpoint_interval = 0.02\nvtk_interval = 0.01\n");
  std::ofstream(dir / "case.toml") << toml;
  ASSERT_EQ(wait_for(spawn_talus({"run", (dir / "case.toml").string(), "--out", (dir / "first").string(), "--quiet"})), 0);
  const fs::path checkpoint = CheckpointSeries::latest(dir / "first");

  std::string longer = with_end_time(toml, "0.06");
  std::ofstream(dir / "longer.toml") << longer;
  ASSERT_EQ(wait_for(spawn_talus({"run", (dir / "longer.toml").string(), "--restart", checkpoint.string(), "--out",
                                  (dir / "second").string(), "--quiet"})),
            0);
  const std::string pvd = slurp(dir / "second" / "vtk" / "particles.pvd");
  EXPECT_NE(pvd.find("<DataSet"), std::string::npos) << pvd;
  EXPECT_TRUE(fs::exists(dir / "second" / "summary.json"));
  fs::remove_all(dir);
}

// A finished chute extended with a later end time and averaging window (how a flow map's cases
// are run on to t = 2000) averages over its own window only, as the uninterrupted run does.
TEST(CheckpointProcess, ExtendedChuteAveragesOnlyItsNewWindow) {
  const fs::path dir = testing::test_folder();
  const auto chute = [&](const std::string& end, const std::string& start) {
    return with_end_time(testing::kChute, end) + "[chute.coarse_graining]\nstart = " + start + "\n";
  };
  std::ofstream(dir / "short.toml") << chute("3.0", "2.0");
  std::ofstream(dir / "long.toml") << chute("6.0", "5.0");
  const auto run = [&](std::vector<std::string> args) { ASSERT_EQ(wait_for(spawn_talus(args)), 0); };
  run({"run", (dir / "long.toml").string(), "--out", (dir / "ref").string(), "--quiet"});
  run({"run", (dir / "short.toml").string(), "--out", (dir / "short").string(), "--quiet"});
  run({"run", (dir / "long.toml").string(), "--restart", CheckpointSeries::latest(dir / "short").string(), "--out",
       (dir / "extended").string(), "--quiet"});

  const nlohmann::json ref = nlohmann::json::parse(slurp(dir / "ref" / "summary.json"));
  const nlohmann::json ext = nlohmann::json::parse(slurp(dir / "extended" / "summary.json"));
  EXPECT_EQ(ext.at("chute").at("averaging_window"), ref.at("chute").at("averaging_window"));
  EXPECT_GE(ext.at("chute").at("averaging_window").at(0).get<double>(), 5.0 - 1e-9);
  for (const char* key : {"h", "mean_velocity", "froude", "mu_macro", "K"}) EXPECT_EQ(ext.at(key), ref.at(key)) << key;
  EXPECT_EQ(slurp(dir / "extended" / "chute_profile.csv"), slurp(dir / "ref" / "chute_profile.csv"));
  EXPECT_EQ(slurp(dir / "extended" / "chute_series.csv"), slurp(dir / "ref" / "chute_series.csv"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace talus
