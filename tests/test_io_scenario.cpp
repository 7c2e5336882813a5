// ScenarioFile: typed getters and every way bad input is reported (FILE:LINE: KEY: message).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "talus/io/scenario_file.h"

using talus::Vec3;
using namespace talus::io;

namespace {

// Line numbers below refer to this text.
const char* kScenario = R"(# line 1
title = "impact"
steps = 1000
dt = 1e-5
gravity = [0, 0, -9.81]
[contact]
normal_stiffness = -3
restitution = 1.5
model = "herz"
friction = "high"
[species.glass]
density = 2500
radii = [1e-3, 2e-3]
[species.steel]
density = 7800
[[walls]]
normal = [0, 0, 1]
[[walls]]
normal = [1, 0, 0]
)";

// The message of the InputError `f` throws; fails the test if it throws nothing.
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

ScenarioFile scenario() { return ScenarioFile::from_string(kScenario, "impact.toml"); }

}  // namespace

TEST(IoScenario, SyntaxErrorNamesFileAndLine) {
  const std::string text = "a = 1\nb = 2\nc = = 3\n";
  const std::string msg = error_of([&] { ScenarioFile::from_string(text, "bad.toml"); });
  EXPECT_TRUE(msg.starts_with("bad.toml:3: ")) << msg;
}

TEST(IoScenario, MissingFileIsInputError) {
  const std::string msg = error_of([] { ScenarioFile::from_file("/nonexistent/x.toml"); });
  EXPECT_EQ(msg, "/nonexistent/x.toml: cannot open: No such file or directory");
}

TEST(IoScenario, TypedGetters) {
  const ScenarioFile f = scenario();
  EXPECT_EQ(f.get<std::string>("title"), "impact");
  EXPECT_EQ(f.get<int>("steps"), 1000);
  EXPECT_EQ(f.get<std::int64_t>("steps"), 1000);
  EXPECT_DOUBLE_EQ(f.get<double>("steps"), 1000.0);  // an integer where a double is expected
  EXPECT_EQ(f.get<double>("dt", positive), 1e-5);
  EXPECT_EQ(f.get<Vec3>("gravity"), Vec3(0, 0, -9.81));
  EXPECT_EQ(f.get<double>("species.glass.density"), 2500.0);
  EXPECT_EQ(f.get<std::vector<double>>("species.glass.radii", positive),
            (std::vector<double>{1e-3, 2e-3}));
  EXPECT_EQ(f.get<Vec3>("walls[1].normal"), Vec3(1, 0, 0));
  EXPECT_EQ(f.get_or<double>("absent.key", 0.25), 0.25);
  EXPECT_EQ(f.get_or<bool>("absent", true), true);
  EXPECT_EQ(f.get_or<double>("dt", 7), 1e-5);
  EXPECT_TRUE(f.has("contact.model"));
  EXPECT_FALSE(f.has("contact.nothing"));
}

TEST(IoScenario, WholeFloatAcceptedAsInteger) {
  const ScenarioFile f = ScenarioFile::from_string("n = 1e6\nm = 2.5\n", "x.toml");
  EXPECT_EQ(f.get<int>("n"), 1000000);
  EXPECT_EQ(error_of([&] { f.get<int>("m"); }), "x.toml:2: m: expected an integer, got 2.5");
}

TEST(IoScenario, MissingRequiredKey) {
  const ScenarioFile f = scenario();
  // The line is that of the nearest present parent, here the [contact] header.
  EXPECT_EQ(error_of([&] { f.get<double>("contact.tangential_stiffness", positive); }),
            "impact.toml:6: contact.tangential_stiffness: missing required key "
            "(expected a positive number)");
  EXPECT_EQ(error_of([&] { f.get<double>("nowhere"); }),
            "impact.toml: nowhere: missing required key (expected a number)");
  EXPECT_EQ(error_of([&] { f.get<Vec3>("walls[2].normal"); }),
            "impact.toml:16: walls[2].normal: missing required key (expected an array of 3 numbers)");
}

TEST(IoScenario, WrongType) {
  const ScenarioFile f = scenario();
  EXPECT_EQ(error_of([&] { f.get<double>("contact.friction"); }),
            "impact.toml:10: contact.friction: expected a number, got a string (\"high\")");
  EXPECT_EQ(error_of([&] { f.get<Vec3>("species.glass.radii"); }),
            "impact.toml:13: species.glass.radii: expected an array of 3 numbers, "
            "got an array of 2 elements");
  EXPECT_EQ(error_of([&] { f.get<bool>("steps"); }),
            "impact.toml:3: steps: expected true or false, got 1000");
  // A path through a value that is not a table.
  EXPECT_EQ(error_of([&] { f.get<double>("dt.x"); }),
            "impact.toml:4: dt: expected a table, got 1e-05");
}

TEST(IoScenario, RangeChecks) {
  const ScenarioFile f = scenario();
  EXPECT_EQ(error_of([&] { f.get<double>("contact.normal_stiffness", positive); }),
            "impact.toml:7: contact.normal_stiffness: must be positive, got -3");
  EXPECT_EQ(error_of([&] { f.get<double>("contact.normal_stiffness", non_negative); }),
            "impact.toml:7: contact.normal_stiffness: must be non-negative, got -3");
  EXPECT_EQ(error_of([&] { f.get<double>("contact.restitution", in_range(0, 1)); }),
            "impact.toml:8: contact.restitution: must be in [0, 1], got 1.5");
  EXPECT_EQ(error_of([&] { f.get<Vec3>("gravity", non_negative); }),
            "impact.toml:5: gravity: element 2 must be non-negative, got -9.81");
  // An optional key present in the file is checked like a required one.
  EXPECT_EQ(error_of([&] { f.get_or<double>("contact.restitution", 0.5, in_range(0, 1)); }),
            "impact.toml:8: contact.restitution: must be in [0, 1], got 1.5");
}

TEST(IoScenario, Choices) {
  const ScenarioFile f = scenario();
  EXPECT_EQ(error_of([&] { f.get_choice("contact.model", {"hertz", "hooke"}); }),
            "impact.toml:9: contact.model: must be one of \"hertz\", \"hooke\", got \"herz\" "
            "(did you mean \"hertz\"?)");
  EXPECT_EQ(f.get_choice_or("contact.law", "hooke", {"hertz", "hooke"}), "hooke");
}

TEST(IoScenario, TablesAndArraysIterate) {
  const ScenarioFile f = scenario();
  EXPECT_EQ(f.table_keys("species"), (std::vector<std::string>{"glass", "steel"}));
  EXPECT_EQ(f.table_keys("contact"),
            (std::vector<std::string>{"normal_stiffness", "restitution", "model", "friction"}));
  EXPECT_EQ(f.array_size("walls"), 2u);
  EXPECT_EQ(f.array_size("nothing"), 0u);
  EXPECT_TRUE(f.table_keys("nothing").empty());
}

TEST(IoScenario, UnknownKeysAllReportedWithSuggestion) {
  const char* text = R"(dt = 1e-5
[contact]
normal_stiffness = 1e5
normal_stifness = 2e5
[[walls]]
normall = [0, 0, 1]
)";
  const ScenarioFile f = ScenarioFile::from_string(text, "typo.toml");
  f.get<double>("dt");
  f.get<double>("contact.normal_stiffness");
  for (std::size_t i = 0; i < f.array_size("walls"); ++i)
    f.get_or<Vec3>("walls[" + std::to_string(i) + "].normal", Vec3(0, 0, 1));
  try {
    f.check_no_unknown_keys();
    FAIL() << "unknown keys not reported";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "typo.toml:4: contact.normal_stifness: unknown key "
              "(did you mean contact.normal_stiffness?)\n"
              "typo.toml:6: walls[0].normall: unknown key (did you mean walls[0].normal?)");
    EXPECT_EQ(e.messages().size(), 2u);
  }
}

TEST(IoScenario, NoUnknownKeysOnceAllRead) {
  const ScenarioFile f = ScenarioFile::from_string("a = 1\n[t]\nb = 2\n", "ok.toml");
  f.get<int>("a");
  f.get<int>("t.b");
  EXPECT_NO_THROW(f.check_no_unknown_keys());
}

TEST(IoScenario, FailNamesKeyLine) {
  const ScenarioFile f = scenario();
  EXPECT_EQ(error_of([&] { f.fail("species.steel.density", "must exceed the fluid density"); }),
            "impact.toml:15: species.steel.density: must exceed the fluid density");
}

TEST(IoScenario, ToTomlRoundTripsFullPrecision) {
  ScenarioFile f = ScenarioFile::from_string("x = 0.1\ny = 0.3333333333333333\nn = 7\n", "p.toml");
  f.set_override("z=2.2250738585072014e-308");
  const std::string text = f.to_toml();
  const ScenarioFile g = ScenarioFile::from_string(text, "copy.toml");
  EXPECT_EQ(g.get<double>("x"), 0.1);
  EXPECT_EQ(g.get<double>("y"), 1.0 / 3.0);
  EXPECT_EQ(g.get<double>("z"), 2.2250738585072014e-308);
  EXPECT_EQ(g.get<int>("n"), 7);
  EXPECT_NE(text.find("# --set z=2.2250738585072014e-308"), std::string::npos) << text;
}

TEST(IoScenario, HasDoesNotCountAsReadAndUnvisitedTablesAreReported) {
  const ScenarioFile f =
      ScenarioFile::from_string("a = 1\n[[walls]]\nn = 1\n[[walls]]\nn = 2\n[empty]\n", "u.toml");
  EXPECT_TRUE(f.has("a"));
  f.get<int>("walls[0].n");
  EXPECT_EQ(error_of([&] { f.check_no_unknown_keys(); }),
            "u.toml:1: a: unknown key\n"
            "u.toml:5: walls[1].n: unknown key (did you mean walls[0].n?)\n"
            "u.toml:6: empty: unknown key");
}

TEST(IoScenario, FromFileUsesPathInMessages) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("talus_io_scenario_" + std::to_string(::getpid()) + ".toml");
  {
    std::ofstream out(path);
    out << "[contact]\n\nnormal_stiffness = -3\n";
  }
  const ScenarioFile f = ScenarioFile::from_file(path);
  EXPECT_EQ(error_of([&] { f.get<double>("contact.normal_stiffness", positive); }),
            path.string() + ":3: contact.normal_stiffness: must be positive, got -3");
  std::filesystem::remove(path);
}

TEST(IoScenario, OverrideKeysListedLast) {
  ScenarioFile f = ScenarioFile::from_string("[species.b]\n[species.a]\n", "o.toml");
  f.set_override("species.c.density=1");
  EXPECT_EQ(f.table_keys("species"), (std::vector<std::string>{"b", "a", "c"}));
}

// A file named in a scenario starts from the scenario's folder; the saved document names it
// absolutely, and the value keeps its line for later messages.
TEST(IoScenario, PathsStartFromTheScenarioFolder) {
  const ScenarioFile f = ScenarioFile::from_string(
      "mesh = \"shapes/../shapes/a.stl\"\nabsolute = \"/data/b.stl\"\nempty = \"\"\n", "case.toml", "examples");
  EXPECT_EQ(f.get_path("mesh"), std::filesystem::path("examples/shapes/a.stl"));
  EXPECT_EQ(f.get_path("absolute"), std::filesystem::path("/data/b.stl"));
  EXPECT_EQ(error_of([&] { f.get_path("empty"); }), "case.toml:3: empty: expected a file name, got an empty string");
  const std::string saved = f.to_toml();
  EXPECT_NE(saved.find((std::filesystem::current_path() / "examples/shapes/a.stl").string()), std::string::npos) << saved;
  EXPECT_EQ(error_of([&] { f.fail("mesh", "unreadable"); }), "case.toml:1: mesh: unreadable");
  // Text without a folder: the current one.
  EXPECT_EQ(ScenarioFile::from_string("m = \"../a.stl\"\n", "x.toml").get_path("m"), std::filesystem::path("../a.stl"));
}
