// Bad scenario input stops before anything runs, with FILE:LINE: KEY: message.
#include <gtest/gtest.h>

#include <string>

#include "talus/io/input_error.h"
#include "talus/scenario/scenario.h"

namespace talus {
namespace {

const std::string kValid = R"(# line 1
[run]
end_time = 0.01

[domain]
lo = [-1.0, -1.0, -1.0]
hi = [1.0, 1.0, 1.0]

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
position = [0.1, 0.0, 0.0]
)";

std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

// Loads `text` and returns the error message ("" if it loaded).
std::string load_error(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    io::ScenarioFile f = io::ScenarioFile::from_string(text, "case.toml");
    for (const auto& o : overrides) f.set_override(o);
    load_scenario(f);
  } catch (const io::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ScenarioErrors, ValidFileLoads) { EXPECT_EQ(load_error(kValid), ""); }

TEST(ScenarioErrors, SyntaxErrorNamesTheLine) {
  EXPECT_EQ(load_error(replace(kValid, "density = 2500", "density = = 2500")).rfind("case.toml:10:", 0), 0u);
}

TEST(ScenarioErrors, UnknownKeyIsReportedWithSuggestion) {
  const std::string e = load_error(replace(kValid, "friction = 0.5", "friction = 0.5\nfricton = 0.3"));
  EXPECT_NE(e.find("case.toml:17: contact.fricton: unknown key"), std::string::npos) << e;
  EXPECT_NE(e.find("contact.friction"), std::string::npos) << e;
}

TEST(ScenarioErrors, NegativeStiffness) {
  const std::string e = load_error(replace(kValid, "normal_stiffness = 1e4", "normal_stiffness = -1e4"));
  EXPECT_EQ(e.rfind("case.toml:14: contact.normal_stiffness: must be positive", 0), 0u) << e;
}

TEST(ScenarioErrors, WrongType) {
  const std::string e = load_error(replace(kValid, "density = 2500", "density = \"heavy\""));
  EXPECT_EQ(e.rfind("case.toml:10: species.glass.density:", 0), 0u) << e;
}

TEST(ScenarioErrors, TimeStepAboveContactTimeOverTen) {
  const std::string e = load_error(replace(kValid, "end_time = 0.01", "end_time = 0.01\ntime_step = 1e-3"));
  EXPECT_EQ(e.rfind("case.toml:4: run.time_step: above t_c/10", 0), 0u) << e;
}

TEST(ScenarioErrors, OverlappingInitialParticles) {
  const std::string e = load_error(replace(kValid, "position = [0.1, 0.0, 0.0]", "position = [0.015, 0.0, 0.0]"));
  EXPECT_EQ(e.rfind("case.toml:24: particles[1].position: overlaps another particle", 0), 0u) << e;
}

TEST(ScenarioErrors, ParticleOutsideTheDomain) {
  const std::string e = load_error(replace(kValid, "position = [0.1, 0.0, 0.0]", "position = [3.0, 0.0, 0.0]"));
  EXPECT_EQ(e.rfind("case.toml:24: particles[1].position: outside the domain", 0), 0u) << e;
}

TEST(ScenarioErrors, UnknownSpecies) {
  const std::string e = load_error(replace(kValid, "species = \"glass\"\nposition = [0.1", "species = \"steel\"\nposition = [0.1"));
  EXPECT_EQ(e.rfind("case.toml:23: particles[1].species: unknown species \"steel\"", 0), 0u) << e;
}

TEST(ScenarioErrors, UnknownModelName) {
  const std::string e = load_error(replace(kValid, "[contact]\n", "[contact]\nmodel = \"hertz\"\n"));
  EXPECT_EQ(e.rfind("case.toml:14: contact.model:", 0), 0u) << e;
}

TEST(ScenarioErrors, ConflictingDampingKeys) {
  const std::string e = load_error(replace(kValid, "friction = 0.5", "friction = 0.5\nnormal_damping = 3.0"));
  EXPECT_NE(e.find("contact.normal_restitution: give only one of"), std::string::npos) << e;
}

TEST(ScenarioErrors, BadOverrideNamesTheOption) {
  const std::string e = load_error(kValid, {"contact.normal_stiffness=-5"});
  EXPECT_EQ(e.rfind("--set contact.normal_stiffness: must be positive", 0), 0u) << e;
}

TEST(ScenarioErrors, BoxHasSixInwardUnitWalls) {
  io::ScenarioFile f = io::ScenarioFile::from_string(
      replace(kValid, "[species.glass]", "[box]\nlo = [-1.0, -1.0, -1.0]\nhi = [1.0, 1.0, 1.0]\n\n[species.glass]"), "case.toml");
  const Scenario s = load_scenario(f);
  ASSERT_EQ(s.world->walls().size(), 6u);
  for (const Wall& w : s.world->walls()) {
    EXPECT_DOUBLE_EQ(norm(w.normal), 1.0) << w.name;
    EXPECT_DOUBLE_EQ(dot(w.normal, Vec3{} - w.origin), 1.0) << w.name;  // the centre is 1 m inside every wall
  }
}

TEST(ScenarioErrors, OnLeaveIsErrorOrDelete) {
  const std::string bad = load_error(replace(kValid, "hi = [1.0, 1.0, 1.0]\n", "hi = [1.0, 1.0, 1.0]\non_leave = \"vanish\"\n"));
  EXPECT_EQ(bad.rfind("case.toml:8: domain.on_leave: must be one of \"error\", \"delete\", got \"vanish\"", 0), 0u) << bad;
  const std::string misspelt = load_error(replace(kValid, "hi = [1.0, 1.0, 1.0]\n", "hi = [1.0, 1.0, 1.0]\non_leaves = \"delete\"\n"));
  EXPECT_NE(misspelt.find("case.toml:8: domain.on_leaves: unknown key (did you mean domain.on_leave?)"), std::string::npos)
      << misspelt;
  EXPECT_EQ(load_error(kValid, {"domain.on_leave=error"}), "");
  io::ScenarioFile f = io::ScenarioFile::from_string(kValid, "case.toml");
  EXPECT_EQ(load_scenario(f).control.on_leave, LeavePolicy::error);  // the default
  f.set_override("domain.on_leave=delete");
  EXPECT_EQ(load_scenario(f).control.on_leave, LeavePolicy::remove);
  const std::string typed = load_error(kValid, {"domain.on_leave=1"});
  EXPECT_EQ(typed.rfind("--set domain.on_leave:", 0), 0u) << typed;
}

TEST(ScenarioErrors, OverrideAppliesToTheRun) {
  io::ScenarioFile f = io::ScenarioFile::from_string(kValid, "case.toml");
  f.set_override("run.end_time=0.5");
  EXPECT_DOUBLE_EQ(load_scenario(f).control.end_time, 0.5);
}

}  // namespace
}  // namespace talus
