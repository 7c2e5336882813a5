// The hopper example (Huet et al. 2021, Appendix B 2) loads with the Table II time step, and a
// [hopper] plug that names no wall stops with FILE:LINE: KEY.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>

#include "talus/io/input_error.h"
#include "talus/scenario/scenario.h"
#include "talus/world/wall_contacts.h"

namespace talus {
namespace {

std::string example_text() {
  std::ifstream in(std::string(TALUS_SOURCE_DIR) + "/examples/hopper.toml");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(HopperScenario, ExampleLoads) {
  io::ScenarioFile f = io::ScenarioFile::from_string(example_text(), "hopper.toml");
  const Scenario sc = load_scenario(f);
  EXPECT_EQ(sc.derived["time_step"].get<double>(), 5.0e-7);  // Table II
  EXPECT_EQ(sc.derived["particles"].get<std::size_t>(), 1000u);
  // Table II gives t_c through k_n and e_n; the time step must resolve it (at least 10 steps).
  EXPECT_GE(sc.derived["steps_per_contact"].get<double>(), 10.0);
  EXPECT_EQ(sc.observers.size(), 1u);
}

// The insertion region reaches closer to the inclined hopper walls than a particle's radius:
// insertion keeps every particle clear of them (a sphere started inside a wall leaves it at tens
// of metres per second), for the spheres and for the tetrapods' bounding spheres.
TEST(HopperScenario, InsertedParticlesStartClearOfTheWalls) {
  for (const char* example : {"hopper.toml", "hopper_tetrapods.toml"}) {
    io::ScenarioFile f = io::ScenarioFile::from_file(std::string(TALUS_SOURCE_DIR) + "/examples/" + example);
    const Scenario sc = load_scenario(f);
    const World& w = *sc.world;
    const ParticleStore& p = w.particles();
    std::size_t near_a_wall = 0;
    for (std::size_t i = 0; i < p.owned; ++i)
      for (const Wall& wall : w.walls()) {
        const double d = dot(p.position[i] - wall.origin, wall.normal);
        const bool faces = !wall.bounded || (d > 0 && wall_faces(wall, wall.origin, p.position[i], p.radius[i]));
        if (faces) EXPECT_GE(d, p.radius[i]) << example << ": particle " << i << " cuts wall " << wall.name;
        if (faces && d < 2 * p.radius[i]) ++near_a_wall;
      }
    EXPECT_GT(near_a_wall, 0u) << example << ": the region does reach the walls, so the test can fail";
  }
}

TEST(HopperScenario, PlugMustNameAWall) {
  std::string text = example_text();
  const std::string from = "plug = \"plug\"";
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos);
  const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n');
  text.replace(at, from.size(), "plug = \"lid\"");
  std::string error;
  try {
    io::ScenarioFile f = io::ScenarioFile::from_string(text, "hopper.toml");
    load_scenario(f);
  } catch (const io::InputError& e) {
    error = e.what();
  }
  EXPECT_EQ(error.rfind("hopper.toml:" + std::to_string(line) + ": hopper.plug:", 0), 0u) << error;
}

}  // namespace
}  // namespace talus
