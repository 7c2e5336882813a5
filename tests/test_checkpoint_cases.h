#pragma once
// Small scenarios with contact history for the checkpoint tests, and bitwise comparisons of
// World states.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "talus/io/scenario_file.h"
#include "talus/scenario/run_loop.h"
#include "talus/scenario/scenario.h"
#include "talus/world/world_state.h"

namespace talus::testing {

// Spheres settling in a closed box with the memory model: tangential and rolling springs alive.
inline const char* kSettlingBox = R"([run]
end_time = 0.1
output_interval = 0.005
steps_per_contact = 20
seed = 3
[domain]
lo = [0.0, 0.0, 0.0]
hi = [0.008, 0.008, 0.03]
[box]
lo = [0.0, 0.0, 0.0]
hi = [0.008, 0.008, 0.03]
[species.glass]
density = 2500
radius = 0.001
[contact]
model = "memory"
max_overlap = 5e-5
impact_speed = 1.0
normal_restitution = 0.45
tangential_restitution = 0.45
friction = 0.5
rolling_friction = 0.45
[contact.wall]
friction = 0.45
rolling_friction = 0.1
[[insert]]
species = "glass"
count = 60
region_lo = [0.001, 0.001, 0.001]
region_hi = [0.007, 0.007, 0.02]
growth = 1e-6
)";

// The periodic chute of Weinhart et al. 2012 (elastic_spring model), shrunk to a 6 x 5 base;
// the layer lands on the rough base after a few time units.
inline const char* kChute = R"([run]
end_time = 6.0
output_interval = 0.25
seed = 2
[chute]
length = 6.0
width = 5.0
base_diameter = 1.0
fill_height = 4.0
angle = 24.0
[contact]
model = "elastic_spring"
normal_stiffness = 2e5
normal_damping_rate = 50
tangential_stiffness_ratio = 0.2857142857142857
tangential_damping_rate = 50
friction = 0.5
)";

// Crosses (Huet et al. 2021) with contact manifolds, dropped under strong gravity (to pile up
// within a few thousand steps) while a pour goes on above them: each contact point has its own
// memory, and the pour's random generator is in mid-stream.
inline const char* kCrossPour = R"([run]
end_time = 0.12
output_interval = 0.005
time_step = 1e-5
seed = 4
[domain]
lo = [0.0, 0.0, 0.0]
hi = [0.05, 0.05, 0.2]
gravity = [0.0, 0.0, -50.0]
[box]
lo = [0.0, 0.0, 0.0]
hi = [0.05, 0.05, 0.2]
open_top = true
[species.cross]
shape = "cross"
density = 770
length = 0.027
width = 0.002
thickness = 0.003
[contact]
model = "memory"
manifold = true
manifold_recycle = 0   # recycled points restart afresh (their budgets are not saved): not the same bits
normal_stiffness = 5e4
normal_restitution = 0.3
tangential_stiffness = 300.0
tangential_damping_factor = 1000.0
friction = 0.46
[contact.wall]
friction = 0.62
[[insert]]
species = "cross"
count = 6
region_lo = [0.012, 0.012, 0.012]
region_hi = [0.038, 0.038, 0.12]
[[pour]]
species = "cross"
count = 8
batch = 2
interval = 0.03
region_lo = [0.012, 0.012, 0.14]
region_hi = [0.038, 0.038, 0.19]
)";

// A fresh, empty folder under the temporary directory, named after the running test.
inline std::filesystem::path test_folder(const std::string& suffix = "") {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("talus_" + std::string(info->test_suite_name()) + "_" + info->name() + suffix +
                                     "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// Runs `toml` into `out` in this process, optionally from a checkpoint.
// `setup` may add observers to the loaded scenario.
inline RunOutcome run_case(const std::string& toml, const std::filesystem::path& out, double checkpoint_interval,
                           std::shared_ptr<io::Checkpoint> restart = nullptr,
                           const std::string& restart_source = "",
                           const std::function<void(Scenario&)>& setup = {}) {
  io::ScenarioFile file = io::ScenarioFile::from_string(toml, "case.toml");
  Scenario scenario = load_scenario(file);
  if (setup) setup(scenario);
  RunOptions options;
  options.out = out;
  options.overwrite = true;
  options.quiet = true;
  options.scenario_toml = file.to_toml();
  if (checkpoint_interval > 0) options.checkpoint_interval = checkpoint_interval;
  options.restart = std::move(restart);
  options.restart_source = restart_source;
  return run_scenario(scenario, options);
}

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

inline bool same_bits(const SubContactList& a, const SubContactList& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    const SubContact &x = a[k], &y = b[k];
    if (!x.same_key(y) || std::memcmp(&x.spring, &y.spring, sizeof(Vec3)) != 0 ||
        std::memcmp(&x.normal_prev, &y.normal_prev, sizeof(Vec3)) != 0 ||
        std::memcmp(&x.point, &y.point, sizeof(Vec3)) != 0 || std::memcmp(&x.force, &y.force, sizeof(Vec3)) != 0 ||
        std::memcmp(&x.overlap, &y.overlap, sizeof(double)) != 0 || std::memcmp(&x.share, &y.share, sizeof(double)) != 0)
      return false;
  }
  return true;
}

// Every part of two World states, bit for bit.
inline void expect_same_state(const WorldState& a, const WorldState& b) {
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(std::memcmp(&a.time, &b.time, sizeof(double)), 0);
  EXPECT_EQ(a.next_gid, b.next_gid);
  EXPECT_EQ(a.rebuilds, b.rebuilds);
  EXPECT_TRUE(same_bits(a.particles.gid, b.particles.gid)) << "particle order";
  EXPECT_TRUE(same_bits(a.particles.position, b.particles.position)) << "positions";
  EXPECT_TRUE(same_bits(a.particles.velocity, b.particles.velocity)) << "velocities";
  EXPECT_TRUE(same_bits(a.particles.orientation, b.particles.orientation)) << "orientations";
  EXPECT_TRUE(same_bits(a.particles.angular_velocity, b.particles.angular_velocity)) << "angular velocities";
  EXPECT_TRUE(same_bits(a.particles.force, b.particles.force)) << "forces";
  EXPECT_TRUE(same_bits(a.particles.torque, b.particles.torque)) << "torques";
  EXPECT_TRUE(same_bits(a.position_at_build, b.position_at_build));
  EXPECT_TRUE(same_bits(a.pair_gid_i, b.pair_gid_i) && same_bits(a.pair_gid_j, b.pair_gid_j)) << "neighbour lists";
  EXPECT_TRUE(same_bits(a.pair_memory.spring, b.pair_memory.spring)) << "tangential springs";
  EXPECT_TRUE(same_bits(a.pair_memory.normal_prev, b.pair_memory.normal_prev)) << "previous normals";
  EXPECT_TRUE(same_bits(a.pair_memory.rolling, b.pair_memory.rolling)) << "rolling springs";
  EXPECT_TRUE(same_bits(a.wall_gid, b.wall_gid) && same_bits(a.wall_index, b.wall_index)) << "wall lists";
  EXPECT_TRUE(same_bits(a.wall_memory.spring, b.wall_memory.spring)) << "wall springs";
  EXPECT_TRUE(same_bits(a.wall_memory.normal_prev, b.wall_memory.normal_prev));
  EXPECT_TRUE(same_bits(a.wall_memory.rolling, b.wall_memory.rolling));
  EXPECT_TRUE(same_bits(a.wall_force, b.wall_force)) << "wall forces";
  ASSERT_EQ(a.pair_sub.size(), b.pair_sub.size());
  for (std::size_t e = 0; e < a.pair_sub.size(); ++e) ASSERT_TRUE(same_bits(a.pair_sub[e], b.pair_sub[e])) << "pair points, entry " << e;
  ASSERT_EQ(a.wall_sub.size(), b.wall_sub.size());
  for (std::size_t e = 0; e < a.wall_sub.size(); ++e) ASSERT_TRUE(same_bits(a.wall_sub[e], b.wall_sub[e])) << "wall points, entry " << e;
}

// Contact memories that are alive (non-zero tangential springs), particle pairs and walls.
inline std::size_t live_springs(const ContactMemory& m) {
  std::size_t n = 0;
  for (const Vec3& s : m.spring) n += norm2(s) > 0;
  return n;
}
inline std::size_t live_point_springs(const std::vector<SubContactList>& lists) {
  std::size_t n = 0;
  for (const auto& list : lists)
    for (const SubContact& s : list) n += norm2(s.spring) > 0;
  return n;
}

}  // namespace talus::testing
