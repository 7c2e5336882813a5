// ScenarioFile::set_override: `--set KEY=VALUE` replaces or creates keys and is blamed by name.
#include <gtest/gtest.h>

#include <string>

#include "talus/io/scenario_file.h"

using talus::Vec3;
using namespace talus::io;

namespace {

const char* kScenario = R"(dt = 1e-5
[contact]
normal_stiffness = 1e5
model = "hertz"
[[walls]]
normal = [0, 0, 1]
)";

template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError thrown";
  return {};
}

ScenarioFile scenario() { return ScenarioFile::from_string(kScenario, "s.toml"); }

}  // namespace

TEST(IoOverride, ReplacesExistingKey) {
  ScenarioFile f = scenario();
  f.set_override("contact.normal_stiffness=2e6");
  EXPECT_EQ(f.get<double>("contact.normal_stiffness"), 2e6);
}

TEST(IoOverride, ErrorsNameTheOverride) {
  ScenarioFile f = scenario();
  f.set_override("contact.normal_stiffness=-3");
  EXPECT_EQ(error_of([&] { f.get<double>("contact.normal_stiffness", positive); }),
            "--set contact.normal_stiffness: must be positive, got -3");
  f.set_override("dt = fast");  // a bare word becomes a string; spaces around '=' are fine
  EXPECT_EQ(error_of([&] { f.get<double>("dt"); }),
            "--set dt: expected a number, got a string (\"fast\")");
}

TEST(IoOverride, ValueTypes) {
  ScenarioFile f = scenario();
  f.set_override("contact.model=hooke");
  f.set_override("quoted=\"a b\"");
  f.set_override("flag=true");
  f.set_override("gravity=[0, -9.81, 0]");
  f.set_override("walls[0].normal=[1,0,0]");
  EXPECT_EQ(f.get_choice("contact.model", {"hertz", "hooke"}), "hooke");
  EXPECT_EQ(f.get<std::string>("quoted"), "a b");
  EXPECT_TRUE(f.get<bool>("flag"));
  EXPECT_EQ(f.get<Vec3>("gravity"), Vec3(0, -9.81, 0));
  EXPECT_EQ(f.get<Vec3>("walls[0].normal"), Vec3(1, 0, 0));
}

TEST(IoOverride, MissingKeyIsCreatedAndRead) {
  ScenarioFile f = scenario();
  f.set_override("damping.viscous.coefficient=0.3");
  EXPECT_EQ(f.get_or<double>("damping.viscous.coefficient", 0.0), 0.3);
  f.get<double>("dt");
  f.get<double>("contact.normal_stiffness");
  f.get<std::string>("contact.model");
  f.get<Vec3>("walls[0].normal");
  EXPECT_NO_THROW(f.check_no_unknown_keys());
}

TEST(IoOverride, UnreadOverrideIsUnknownKey) {
  ScenarioFile f = scenario();
  f.set_override("contact.normal_stifness=2e6");
  f.get<double>("dt");
  f.get<double>("contact.normal_stiffness");
  f.get<std::string>("contact.model");
  f.get<Vec3>("walls[0].normal");
  EXPECT_EQ(error_of([&] { f.check_no_unknown_keys(); }),
            "--set contact.normal_stifness: unknown key (did you mean contact.normal_stiffness?)");
}

TEST(IoOverride, BadOverrides) {
  ScenarioFile f = scenario();
  EXPECT_EQ(error_of([&] { f.set_override("dt"); }), "--set dt: expected KEY=VALUE");
  EXPECT_EQ(error_of([&] { f.set_override("a..b=1"); }),
            "--set a..b: malformed key (empty key name)");
  EXPECT_EQ(error_of([&] { f.set_override("dt.x=1"); }),
            "--set dt.x: dt is 1e-05, not a table");
  EXPECT_EQ(error_of([&] { f.set_override("walls[3].normal=[0,0,1]"); }),
            "--set walls[3].normal: walls has only 1 entry");
}

TEST(IoOverride, ParentOverrideBlamesParent) {
  ScenarioFile f = scenario();
  f.set_override("contact={normal_stiffness = -1}");
  EXPECT_EQ(error_of([&] { f.get<double>("contact.normal_stiffness", positive); }),
            "--set contact: contact.normal_stiffness: must be positive, got -1");
  EXPECT_FALSE(f.has("contact.model"));  // the whole table was replaced
}
