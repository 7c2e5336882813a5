// The hopper example (Huet et al. 2021, Appendix B 2) loads with the Table II time step, and a
// [hopper] plug that names no wall stops with FILE:LINE: KEY.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>

#include "talus/io/input_error.h"
#include "talus/scenario/scenario.h"

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
