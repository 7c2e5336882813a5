// The blow-up guard (world/state_guard.h, scenario/blowup_guard.h): a state no valid step leads
// to (not finite, moving more than a radius per step, outside a non-periodic face) stops the run
// with an error naming the step, the particles and the quantity, a state file and exit status 3;
// with domain.on_leave = "delete" a particle that leaves is removed and counted instead.
// Legitimate runs (a chute with saltating grains over a base that reaches below the domain's
// floor, a dam break) never trip it.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

#include <nlohmann/json.hpp>

#include "talus/io/snapshot_file.h"
#include "talus/scenario/checkpoint_series.h"
#include "talus/world/state_guard.h"
#include "test_checkpoint_cases.h"

namespace talus {
namespace {

namespace fs = std::filesystem;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Two glass beads in a closed 2 m box without walls or gravity; t_c = 2.3 ms, dt = 46 us.
// Bead 1 is thrown along x (speed set per test); bead 0 rests at the centre.
std::string two_beads(const std::string& velocity, const std::string& extra = "") {
  return R"([run]
end_time = 0.3
output_interval = 0.01
[domain]
lo = [-1.0, -1.0, -1.0]
hi = [1.0, 1.0, 1.0]
gravity = [0.0, 0.0, 0.0]
)" + extra + R"(
[species.glass]
density = 2500
radius = 0.01
[contact]
normal_stiffness = 1e4
normal_restitution = 0.5
friction = 0.5
[[particles]]
species = "glass"
position = [0.0, 0.0, 0.0]
[[particles]]
species = "glass"
position = [0.5, 0.0, 0.0]
velocity = )" + velocity + "\n";
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

nlohmann::json read_summary(const fs::path& dir) { return nlohmann::json::parse(slurp(dir / "summary.json")); }

// Every null in a JSON document, by path.
void find_nulls(const nlohmann::json& j, const std::string& path, std::vector<std::string>& found) {
  if (j.is_null()) found.push_back(path);
  if (j.is_object())
    for (auto it = j.begin(); it != j.end(); ++it) find_nulls(it.value(), path + "/" + it.key(), found);
  if (j.is_array())
    for (std::size_t k = 0; k < j.size(); ++k) find_nulls(j[k], path + "/" + std::to_string(k), found);
}

struct Finished {
  int status = -1;
  std::string stderr_text;
};

// `talus run FILE --out DIR ARGS...`, as a user runs it: exit status and what it said on stderr.
Finished talus_run(const fs::path& scenario, const fs::path& out, const std::string& args = "") {
  const fs::path err = out.string() + ".stderr";
  const std::string command = std::string(TALUS_BINARY_DIR) + "/talus run " + scenario.string() + " --out " +
                              out.string() + " --overwrite --quiet --threads 1 " + args + " > /dev/null 2> " +
                              err.string();
  const int raw = std::system(command.c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(err)};
}

// --- the test itself, particle by particle ---------------------------------------------------

ParticleStore one_particle(const Vec3& x, double radius) {
  ParticleStore p;
  p.resize(1);
  p.owned = 1;
  p.position[0] = x;
  p.radius[0] = radius;
  return p;
}

TEST(StateGuard, EachFaultIsFoundAndOnlyIt) {
  Domain box;
  box.lo = {0, 0, 0};
  box.hi = {1, 1, 1};
  const double dt = 1e-3, r = 0.01;
  const GuardBounds bounds(box, dt);
  auto faults = [&](const ParticleStore& p) { return particle_faults(p, 0, bounds); };

  ParticleStore p = one_particle({0.5, 0.5, 0.5}, r);
  p.velocity[0] = {0, 0, 9.9};  // 0.99 r per step: fast, still resolved
  p.angular_velocity[0] = {0, 990, 0};
  EXPECT_EQ(faults(p), 0u);
  p.velocity[0] = {0, 0, 10.1};
  EXPECT_EQ(faults(p), kTooFast);
  p.velocity[0] = {1e200, 0, 0};  // |v|^2 overflows: still too fast, not "not finite"
  EXPECT_EQ(faults(p), kTooFast);
  p.velocity[0] = {};
  p.angular_velocity[0] = {0, 1010, 0};
  EXPECT_EQ(faults(p), kSpinning);
  p.angular_velocity[0] = {};
  for (Vec3* quantity : {&p.position[0], &p.velocity[0], &p.angular_velocity[0], &p.force[0]}) {
    const Vec3 kept = *quantity;
    quantity->y = kNaN;
    EXPECT_TRUE(faults(p) & kNotFinite);
    quantity->y = std::numeric_limits<double>::infinity();
    EXPECT_TRUE(faults(p) & kNotFinite);
    *quantity = kept;
  }
  EXPECT_EQ(faults(p), 0u);
}

TEST(StateGuard, AParticleHasLeftOnlyWhenItIsWhollyOutsideANonPeriodicFace) {
  Domain box;
  box.lo = {0, 0, 0};
  box.hi = {1, 1, 1};
  box.periodic[0] = true;
  const double r = 0.01;
  const GuardBounds bounds(box, 1e-4);
  auto faults = [&](const Vec3& x) { return particle_faults(one_particle(x, r), 0, bounds); };
  EXPECT_EQ(faults({0.5, 0.5, 0.99 * r}), 0u);       // resting on a floor at the domain's face, overlapping it
  EXPECT_EQ(faults({0.5, 0.5, -0.99 * r}), 0u);      // pushed half through: part of it is still inside
  EXPECT_EQ(faults({0.5, 1 + 0.99 * r, 0.5}), 0u);
  EXPECT_EQ(faults({0.5, 0.5, -1.01 * r}), kOutside);
  EXPECT_EQ(faults({0.5, 1 + 1.01 * r, 0.5}), kOutside);
  EXPECT_EQ(faults({-3.0, 0.5, 0.5}), 0u);  // x is periodic: positions wrap at the next rebuild
  EXPECT_EQ(faults({7.0, 0.5, 0.5}), 0u);
}

// --- whole runs ----------------------------------------------------------------------------

TEST(BlowUpGuard, SphereLaunchedAt1e200StopsTheRunWithStatus3) {
  const fs::path dir = testing::test_folder();
  std::ofstream(dir / "case.toml") << two_beads("[1e200, 0.0, 0.0]");
  const Finished f = talus_run(dir / "case.toml", dir / "out");
  EXPECT_EQ(f.status, 3) << f.stderr_text;
  // One line naming the step, the particle and the quantity.
  EXPECT_EQ(f.stderr_text.rfind("talus: error: step 0 (t = 0 s): particle 1: moves ", 0), 0u) << f.stderr_text;
  EXPECT_NE(f.stderr_text.find("radii per step (speed 1e+200 m/s"), std::string::npos) << f.stderr_text;
  EXPECT_NE(f.stderr_text.find("blowup_state.h5"), std::string::npos) << f.stderr_text;
  EXPECT_EQ(std::count(f.stderr_text.begin(), f.stderr_text.end(), '\n'), 1) << f.stderr_text;

  const nlohmann::json s = read_summary(dir / "out");
  EXPECT_EQ(s["stop_reason"], "blow_up");
  EXPECT_EQ(s["blow_up"]["quantity"], "speed");
  EXPECT_EQ(s["blow_up"]["particles"], nlohmann::json::array({1}));
  EXPECT_EQ(s["blow_up"]["particle_states"][0]["velocity"][0], 1e200);
  // Its kinetic energy overflows: written as "inf", never as a null that reads "not measured".
  EXPECT_EQ(s["energies"]["kinetic_translational"], "inf");
  std::vector<std::string> nulls;
  find_nulls(s, "", nulls);
  EXPECT_TRUE(nulls.empty()) << nulls.front();
  // The state, for the post-mortem; no checkpoint of it (resuming would blow up again).
  const Snapshot dumped = io::read_snapshot_file(dir / "out" / "blowup_state.h5");
  ASSERT_EQ(dumped.particles.size(), 2u);
  EXPECT_EQ(dumped.particles[1].velocity.x, 1e200);
  EXPECT_FALSE(fs::exists(dir / "out" / "checkpoints" / "latest.h5"));
  EXPECT_TRUE(fs::exists(dir / "out" / "timeseries.csv"));
  EXPECT_FALSE(fs::exists(dir / "out" / "timeseries.csv.partial"));
  fs::remove_all(dir);
}

// Sets the x velocity of one particle to NaN once the clock reaches `at`.
class NanInjector : public RunObserver {
 public:
  // `injected` outlives the run (the scenario, and this observer with it, ends with the run).
  NanInjector(std::uint32_t gid, double at, std::uint64_t& injected) : gid_(gid), at_(at), injected_step_(injected) {}
  std::string name() const override { return "nan_injector"; }
  double next_step_event(const World& /*world*/) const override {
    return injected_step_ ? std::numeric_limits<double>::infinity() : at_;
  }
  void after_step(World& world) override {
    if (injected_step_ || world.time() < at_) return;
    const std::int32_t i = world.index_of_gid()[gid_];
    world.particles_mutable().velocity[static_cast<std::size_t>(i)].x = kNaN;
    injected_step_ = world.step_count();
  }

 private:
  std::uint32_t gid_;
  double at_;
  std::uint64_t& injected_step_;
};

TEST(BlowUpGuard, NanInAVelocityIsCaughtWithinABatch) {
  const fs::path dir = testing::test_folder();
  std::uint64_t injected = 0;
  const RunOutcome outcome = testing::run_case(two_beads("[0.0, 0.1, 0.0]"), dir / "out", 0, nullptr, "", [&](Scenario& sc) {
    sc.observers.push_back(std::make_unique<NanInjector>(1, 0.05, injected));
  });
  ASSERT_EQ(outcome.stop_reason, "blow_up");
  const nlohmann::json s = read_summary(dir / "out");
  const std::uint64_t step = s["blow_up"]["step"].get<std::uint64_t>();
  ASSERT_GT(injected, 0u);
  EXPECT_GT(step, injected);
  EXPECT_LE(step, injected + 64);  // found at the end of the next batch
  EXPECT_EQ(outcome.error.rfind("step " + std::to_string(step) + " (t = ", 0), 0u) << outcome.error;
  // The drift has carried the NaN into the position; the velocity comes first, as the cause.
  EXPECT_NE(outcome.error.find("s): particle 1: velocity and position are not finite"), std::string::npos)
      << outcome.error;
  EXPECT_EQ(s["blow_up"]["quantity"], "velocity");
  EXPECT_EQ(s["blow_up"]["particle_states"][0]["velocity"][0], "nan");
  EXPECT_EQ(s["steps"], step);
  std::vector<std::string> nulls;
  find_nulls(s, "", nulls);
  EXPECT_TRUE(nulls.empty()) << nulls.front();
  EXPECT_TRUE(fs::exists(dir / "out" / "blowup_state.h5"));
  // The last time-series row says nan, as text, not an empty cell.
  const std::string csv = slurp(dir / "out" / "timeseries.csv");
  EXPECT_NE(csv.substr(csv.rfind('\n', csv.size() - 2)).find("nan"), std::string::npos);
  fs::remove_all(dir);
}

TEST(BlowUpGuard, ParticleLeavingTheBoxStopsTheRunOrIsDeletedAndCounted) {
  const fs::path dir = testing::test_folder();
  std::ofstream(dir / "case.toml") << two_beads("[5.0, 0.0, 0.0]");  // reaches x = 1 + r after about 0.1 s
  const Finished error = talus_run(dir / "case.toml", dir / "error");
  EXPECT_EQ(error.status, 3) << error.stderr_text;
  EXPECT_NE(error.stderr_text.find("): particle 1: left the domain on x (x = 1.0"), std::string::npos) << error.stderr_text;
  EXPECT_NE(error.stderr_text.find(" m, domain.hi.x = 1 m)"), std::string::npos) << error.stderr_text;
  EXPECT_EQ(read_summary(dir / "error")["blow_up"]["quantity"], "position");

  const Finished removed = talus_run(dir / "case.toml", dir / "delete", "--set domain.on_leave=delete");
  EXPECT_EQ(removed.status, 0) << removed.stderr_text;
  const nlohmann::json s = read_summary(dir / "delete");
  EXPECT_EQ(s["stop_reason"], "end_time");
  EXPECT_EQ(s["particles"], 1);
  EXPECT_EQ(s["particles_left_domain"], 1);
  EXPECT_FALSE(s.contains("blow_up"));
  // The count is a time-series column: 0 at the start, 1 at the end.
  std::istringstream csv(slurp(dir / "delete" / "timeseries.csv"));
  std::string header, first, line, last;
  std::getline(csv, header);
  std::getline(csv, first);
  while (std::getline(csv, line)) last = line;
  EXPECT_EQ(header.substr(header.rfind(',') + 1), "particles_left_domain");
  EXPECT_EQ(first.substr(first.rfind(',') + 1), "0");
  EXPECT_EQ(last.substr(last.rfind(',') + 1), "1");
  fs::remove_all(dir);
}

// The settling box with an open top and one more bead thrown up out of it: the bead is deleted
// early, and a run restarted from a later checkpoint keeps the count and ends bit for bit where
// the uninterrupted run ends.
TEST(BlowUpGuard, DeletedCountCrossesACheckpointRestart) {
  std::string toml = testing::kSettlingBox;
  toml.replace(toml.find("[box]"), 5, "on_leave = \"delete\"\n[box]\nopen_top = true");
  toml += R"([[particles]]
species = "glass"
position = [0.004, 0.004, 0.025]
velocity = [0.0, 0.0, 3.0]
)";
  const fs::path dir = testing::test_folder();
  testing::run_case(toml, dir / "a", 0.06);
  const fs::path first = CheckpointSeries::list(dir / "a" / "checkpoints").front();
  auto checkpoint = std::make_shared<io::Checkpoint>(io::read_checkpoint(first));
  EXPECT_EQ(checkpoint->run.at("particles_left_domain"), 1);
  EXPECT_EQ(checkpoint->world.particles.owned, 60u);
  testing::run_case(toml, dir / "b", 0, checkpoint, first.string());
  EXPECT_EQ(read_summary(dir / "b")["particles_left_domain"], 1);
  const io::Checkpoint a = io::read_checkpoint(CheckpointSeries::latest(dir / "a"));
  const io::Checkpoint b = io::read_checkpoint(CheckpointSeries::latest(dir / "b"));
  testing::expect_same_state(a.world, b.world);
  EXPECT_EQ(slurp(dir / "a" / "timeseries.csv"), slurp(dir / "b" / "timeseries.csv"));
  fs::remove_all(dir);
}

// --- removal keeps the rest of the world intact ------------------------------------------

TEST(BlowUpGuard, RemovingParticlesKeepsTheOthersContactMemories) {
  io::ScenarioFile f = io::ScenarioFile::from_string(testing::kSettlingBox, "box.toml");
  Scenario sc = load_scenario(f);
  World& world = *sc.world;
  world.run(static_cast<std::uint64_t>(0.06 / world.settings().time_step));  // settled into a pile
  const WorldState before = world.capture_state();
  const std::size_t springs = testing::live_springs(before.pair_memory);
  ASSERT_GT(springs, 20u);
  // The highest bead goes, with whatever contacts it has.
  const ParticleStore& p = world.particles();
  std::size_t top = 0;
  for (std::size_t i = 0; i < p.owned; ++i)
    if (p.position[i].z > p.position[top].z) top = i;
  const std::uint32_t gone = p.gid[top];
  std::size_t its_springs = 0;
  for (std::size_t e = 0; e < before.pair_gid_i.size(); ++e)
    its_springs += (before.pair_gid_i[e] == gone || before.pair_gid_j[e] == gone) && norm2(before.pair_memory.spring[e]) > 0;
  EXPECT_EQ(world.remove_particles_if([&](std::size_t i) { return i == top; }), 1u);
  EXPECT_EQ(world.remove_particles_if([](std::size_t) { return false; }), 0u);
  world.make_ready();
  const WorldState after = world.capture_state();
  EXPECT_EQ(after.particles.owned, before.particles.owned - 1);
  for (const std::uint32_t g : after.particles.gid) EXPECT_NE(g, gone);
  // Every other remembered contact is carried over with its spring. The forces are computed
  // afresh for the new set-up (as after a pour), which sets the spring of a sliding contact
  // from the Coulomb limit with the velocities of now: those move by a few per cent.
  EXPECT_EQ(testing::live_springs(after.pair_memory), springs - its_springs);
  std::size_t unchanged = 0;
  for (std::size_t e = 0; e < after.pair_gid_i.size(); ++e) {
    if (norm2(after.pair_memory.spring[e]) == 0) continue;
    // The rebuild may list a pair the other way round, its spring then seen from the other side.
    double closest = 1e300;
    for (std::size_t k = 0; k < before.pair_gid_i.size(); ++k) {
      const Vec3 spring = before.pair_memory.spring[k];
      if (before.pair_gid_i[k] == after.pair_gid_i[e] && before.pair_gid_j[k] == after.pair_gid_j[e])
        closest = norm(spring - after.pair_memory.spring[e]) / norm(spring);
      if (before.pair_gid_i[k] == after.pair_gid_j[e] && before.pair_gid_j[k] == after.pair_gid_i[e])
        closest = norm(spring + after.pair_memory.spring[e]) / norm(spring);
    }
    EXPECT_LE(closest, 0.1) << "entry " << e;
    unchanged += closest == 0;
  }
  EXPECT_GT(unchanged, (springs - its_springs) / 2);
  world.run(100);  // and the world steps on
  EXPECT_EQ(scan_state(world.particles(), world.settings().domain, world.settings().time_step), 0u);
  // Down to none at all.
  world.remove_particles_if([](std::size_t) { return true; });
  world.run(10);
  EXPECT_EQ(world.owned_count(), 0u);
}

TEST(BlowUpGuard, RemovingARigidBodyKeepsTheOthersContactPoints) {
  io::ScenarioFile f = io::ScenarioFile::from_string(testing::kCrossPour, "crosses.toml");
  Scenario sc = load_scenario(f);
  World& world = *sc.world;
  world.run(12000);  // the six inserted crosses lie on the floor and on each other
  const WorldState before = world.capture_state();
  ASSERT_GT(testing::live_point_springs(before.pair_sub), 0u);
  ASSERT_GT(testing::live_point_springs(before.wall_sub), 0u);
  const ParticleStore& p = world.particles();
  std::size_t top = 0;
  for (std::size_t i = 0; i < p.owned; ++i)
    if (p.position[i].z > p.position[top].z) top = i;
  world.remove_particles_if([&](std::size_t i) { return i == top; });
  world.make_ready();
  const WorldState after = world.capture_state();
  EXPECT_EQ(after.particles.owned, before.particles.owned - 1);
  // Contact points between the crosses left, and with the floor, keep their springs.
  EXPECT_GT(testing::live_point_springs(after.pair_sub), 0u);
  EXPECT_GT(testing::live_point_springs(after.wall_sub), 0u);
  world.run(500);
  EXPECT_EQ(scan_state(world.particles(), world.settings().domain, world.settings().time_step), 0u);
}

// --- legitimate runs never trip it -------------------------------------------------------

// examples/chute.toml on a 6 x 5 base, H = 4, for 1.5 time units with profiles over the last half:
// the layer falls onto a rough base whose fixed spheres reach below the domain's floor
// (z = -2) and grains bounce off it.
TEST(BlowUpGuard, ShortChuteNeverTripsIt) {
  io::ScenarioFile f = io::ScenarioFile::from_file(fs::path(TALUS_SOURCE_DIR) / "examples" / "chute.toml");
  for (const char* o : {"run.end_time=1.5", "chute.length=6", "chute.width=5", "chute.fill_height=4",
                        "chute.coarse_graining.start=1", "chute.coarse_graining.end=1.5"})
    f.set_override(o);
  Scenario sc = load_scenario(f);
  const World& world = *sc.world;
  double lowest_reach = 0;
  for (std::size_t i = 0; i < world.particles().owned; ++i)
    lowest_reach = std::min(lowest_reach, world.particles().position[i].z - world.particles().radius[i]);
  EXPECT_LT(lowest_reach, world.settings().domain.lo.z);
  const fs::path dir = testing::test_folder();
  RunOptions opt;
  opt.out = dir / "out";
  opt.quiet = true;
  opt.threads = 1;
  opt.scenario_toml = f.to_toml();
  const RunOutcome outcome = run_scenario(sc, opt);
  ASSERT_EQ(outcome.stop_reason, "end_time") << outcome.error;
  EXPECT_EQ(read_summary(opt.out)["particles_left_domain"], 0);
  fs::remove_all(dir);
}

// tests/data/dam_break_narrow.toml with 30 crosses dropped from 3 cm, at the largest time step the
// loader allows (t_c / 10, where |v| dt / r is largest): the gate is pulled up (43 m/s^2, with
// friction on the crosses) after 0.15 s and the column collapses for 0.07 s.
TEST(BlowUpGuard, ShortDamBreakNeverTripsIt) {
  io::ScenarioFile f = io::ScenarioFile::from_file(fs::path(TALUS_SOURCE_DIR) / "tests" / "data" / "dam_break_narrow.toml");
  for (const char* o : {"run.end_time=0.22", "run.time_step=5e-6", "run.vtk_interval=0", "dam_break.count=30",
                        "dam_break.fill_height=0.03", "dam_break.settle_min_time=0", "dam_break.settle_max_time=0.15"})
    f.set_override(o);
  Scenario sc = load_scenario(f);
  const fs::path dir = testing::test_folder();
  RunOptions opt;
  opt.out = dir / "out";
  opt.quiet = true;
  opt.threads = 1;
  opt.scenario_toml = f.to_toml();
  const RunOutcome outcome = run_scenario(sc, opt);
  ASSERT_NE(outcome.stop_reason, "blow_up") << outcome.error;
  const nlohmann::json s = read_summary(opt.out);
  EXPECT_NE(s["dam_break"]["phase"], "settling") << s.dump(1);  // the gate did open
  fs::remove_all(dir);
}

}  // namespace
}  // namespace talus
