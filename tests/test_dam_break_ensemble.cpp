// Ensembles (Huet et al. 2021, Fig. 9: each case repeated with different initial
// microstructures): the statistics of synthetic summaries, the stable fraction and the verdict
// repeatable / intermittent; and `talus ensemble` running seeds of a tiny scenario.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <sys/wait.h>

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Writes seed_<k>/summary.json for every regime, with runout ratios and a nested flag.
void write_summaries(const fs::path& dir, const std::vector<std::string>& regimes, const std::vector<double>& runout,
                     const std::vector<bool>& static_reached) {
  for (std::size_t k = 0; k < regimes.size(); ++k) {
    fs::create_directories(dir / ("seed_" + std::to_string(k + 1)));
    json s = {{"regime", regimes[k]}, {"L0", 0.03}, {"dam_break", {{"runout_ratio", runout[k]},
                                                                    {"before_gate", {{"static_reached", static_reached[k]}}}}}};
    std::ofstream(dir / ("seed_" + std::to_string(k + 1)) / "summary.json") << s.dump();
  }
}

json aggregate(const fs::path& dir) {
  const std::string cmd = "/usr/bin/python3 " + std::string(TALUS_SOURCE_DIR) + "/tools/dam_break_ensemble.py aggregate " +
                          dir.string() + " > /dev/null";
  EXPECT_EQ(std::system(cmd.c_str()), 0);
  return json::parse(std::ifstream(dir / "ensemble.json"));
}

TEST(DamBreakEnsemble, StatisticsStableFractionAndVerdict) {
  const fs::path dir = fresh_dir("talus_ensemble_mixed");
  const std::vector<double> runout = {1.0, 2.0, 3.5, 6.0};
  write_summaries(dir, {"stable", "collapsed", "collapsed", "fractured"}, runout, {true, false, true, true});
  const json e = aggregate(dir);
  double mean = 0, var = 0;
  for (double v : runout) mean += v / runout.size();
  for (double v : runout) var += (v - mean) * (v - mean) / (runout.size() - 1);  // sample variance
  const json& r = e["measurements"]["dam_break.runout_ratio"];
  EXPECT_EQ(e["runs"], 4);
  EXPECT_NEAR(r["mean"].get<double>(), mean, 1e-12);
  EXPECT_NEAR(r["std"].get<double>(), std::sqrt(var), 1e-12);
  EXPECT_EQ(r["min"].get<double>(), 1.0);
  EXPECT_EQ(r["max"].get<double>(), 6.0);
  // A flag averages to the share of runs where it held: 3 of 4.
  EXPECT_NEAR(e["measurements"]["dam_break.before_gate.static_reached"]["mean"].get<double>(), 0.75, 1e-12);
  EXPECT_NEAR(e["stable_fraction"].get<double>(), 0.25, 1e-12);
  EXPECT_EQ(e["regime_counts"]["collapsed"], 2);
  EXPECT_EQ(e["verdict"], "intermittent");  // one stable run, three that moved
  EXPECT_EQ(e["majority_regime"], "collapsed");
  // The table repeats the statistics.
  std::ifstream csv(dir / "ensemble.csv");
  std::string line;
  bool found = false;
  while (std::getline(csv, line)) found |= line.rfind("dam_break.runout_ratio,4,", 0) == 0;
  EXPECT_TRUE(found);
}

TEST(DamBreakEnsemble, AllAlikeIsRepeatable) {
  const fs::path collapsed = fresh_dir("talus_ensemble_collapsed");
  write_summaries(collapsed, {"collapsed", "fractured", "collapsed"}, {2, 2, 2}, {true, true, true});
  const json a = aggregate(collapsed);
  EXPECT_EQ(a["verdict"], "repeatable");  // no run stable: the collapse mode may differ
  EXPECT_EQ(a["stable_fraction"].get<double>(), 0.0);
  EXPECT_EQ(a["measurements"]["dam_break.runout_ratio"]["std"].get<double>(), 0.0);
  const fs::path stable = fresh_dir("talus_ensemble_stable");
  write_summaries(stable, {"stable", "stable"}, {0, 0}, {true, true});
  const json b = aggregate(stable);
  EXPECT_EQ(b["verdict"], "repeatable");
  EXPECT_EQ(b["stable_fraction"].get<double>(), 1.0);
  const fs::path single = fresh_dir("talus_ensemble_single");
  write_summaries(single, {"stable"}, {0}, {true});
  EXPECT_EQ(aggregate(single)["verdict"], "undetermined");  // one run cannot show intermittency
}

// Five spheres dropped in a box: a run of a few milliseconds.
void write_drop_scenario(const fs::path& file) {
  fs::copy_file(fs::path(TALUS_SOURCE_DIR) / "tests" / "data" / "five_spheres_drop.toml", file,
                fs::copy_options::overwrite_existing);
}

int run_command(const std::string& cmd) {
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

const std::string kTalus = std::string(TALUS_BINARY_DIR) + "/talus";

TEST(DamBreakEnsemble, CommandRunsEverySeed) {
  const fs::path dir = fresh_dir("talus_ensemble_command");
  write_drop_scenario(dir / "drop.toml");
  const std::string talus = kTalus;
  ASSERT_EQ(std::system((talus + " ensemble " + (dir / "drop.toml").string() + " --seeds 3 --jobs 2 --out " +
                         (dir / "out").string() + " --set run.end_time=0.001 > /dev/null").c_str()), 0);
  const json e = json::parse(std::ifstream(dir / "out" / "ensemble.json"));
  EXPECT_EQ(e["runs"], 3);
  EXPECT_EQ(e["measurements"]["particles"]["mean"].get<double>(), 5.0);
  EXPECT_FALSE(e.contains("verdict"));  // no regime in these summaries
  for (int k = 1; k <= 3; ++k) {
    // Each run got its own seed and the common override.
    std::ifstream toml(dir / "out" / ("seed_" + std::to_string(k)) / "scenario.toml");
    const std::string text((std::istreambuf_iterator<char>(toml)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("seed = " + std::to_string(k)), std::string::npos) << text;
    EXPECT_NE(text.find("end_time = 0.001"), std::string::npos) << text;
  }
}

// Under mpirun the seeds are spread over the ranks: rank 0 drives and runs one, rank 1 the others
// as they come (tools/case_pool.py); the ensemble is the same as on one process.
TEST(DamBreakEnsemble, CommandSpreadsSeedsOverRanks) {
  const fs::path dir = fresh_dir("talus_ensemble_mpi");
  write_drop_scenario(dir / "drop.toml");
  ASSERT_EQ(run_command("mpirun --oversubscribe --allow-run-as-root -n 2 " + kTalus + " ensemble " +
                        (dir / "drop.toml").string() + " --seeds 4 --out " + (dir / "out").string() +
                        " --set run.end_time=0.001 > " + (dir / "log.txt").string() + " 2>&1"),
            0)
      << read_text(dir / "log.txt");
  EXPECT_NE(read_text(dir / "log.txt").find("ensemble: 2 ranks"), std::string::npos) << read_text(dir / "log.txt");
  const json e = json::parse(std::ifstream(dir / "out" / "ensemble.json"));
  EXPECT_EQ(e["runs"], 4);
  for (int k = 1; k <= 4; ++k)
    EXPECT_TRUE(fs::exists(dir / "out" / ("seed_" + std::to_string(k)) / "summary.json")) << "seed " << k;
}

// `--slurm FILE` writes a job array of one run per task; running its tasks one by one, as Slurm
// would, runs every seed, and the last task alone writes the ensemble.
TEST(DamBreakEnsemble, SlurmArrayRunsOneSeedPerTask) {
  const fs::path dir = fresh_dir("talus_ensemble_slurm");
  write_drop_scenario(dir / "drop.toml");
  const fs::path script = dir / "ensemble.sbatch";
  ASSERT_EQ(run_command("cd " + dir.string() + " && " + kTalus + " ensemble drop.toml --seeds 3 --out out" +
                        " --set run.end_time=0.001 --slurm " + script.string() + " > /dev/null"),
            0);
  const std::string text = read_text(script);
  EXPECT_NE(text.find("#SBATCH --array=0-2"), std::string::npos) << text;
  EXPECT_FALSE(fs::exists(dir / "out" / "seed_1")) << "--slurm runs nothing";
  for (int task = 0; task < 3; ++task) {
    EXPECT_FALSE(fs::exists(dir / "out" / "ensemble.json")) << "written before task " << task;
    ASSERT_EQ(run_command("SLURM_ARRAY_TASK_ID=" + std::to_string(task) + " bash " + script.string() + " > " +
                          (dir / "task.log").string() + " 2>&1"),
              0)
        << read_text(dir / "task.log");
    EXPECT_TRUE(fs::exists(dir / "out" / ("seed_" + std::to_string(task + 1)) / "summary.json"));
  }
  const json e = json::parse(std::ifstream(dir / "out" / "ensemble.json"));
  EXPECT_EQ(e["runs"], 3);
}

}  // namespace
