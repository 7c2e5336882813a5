// Bad scenario input stops before anything runs, with FILE:LINE: KEY: message.
#include <gtest/gtest.h>

#include <string>

#include "talus/io/input_error.h"
#include "talus/scenario/scenario.h"
#include "talus/world/world.h"

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

TEST(ScenarioErrors, NarrowPhaseReuseIsABooleanAndRefitAFraction) {
  const std::string e = load_error(replace(kValid, "friction = 0.5", "friction = 0.5\nnarrow_phase_reuse = 3"));
  EXPECT_EQ(e.rfind("case.toml:17: contact.narrow_phase_reuse", 0), 0u) << e;
  EXPECT_EQ(load_error(replace(kValid, "friction = 0.5", "friction = 0.5\nnarrow_phase_reuse = false")), "");
  const std::string refit = load_error(replace(kValid, "friction = 0.5", "friction = 0.5\nmanifold_refit = 0.8"));
  EXPECT_EQ(refit.rfind("case.toml:17: contact.manifold_refit", 0), 0u) << refit;
  EXPECT_EQ(load_error(replace(kValid, "friction = 0.5", "friction = 0.5\nmanifold_refit = 0.1")), "");
}

// The recycle margin is a travel in metres, for manifolds with reuse only, and not beside the refit.
TEST(ScenarioErrors, RecycleMarginIsBoundedAndNeedsManifoldsWithReuse) {
  auto with = [](const std::string& lines) { return replace(kValid, "friction = 0.5", "friction = 0.5\n" + lines); };
  const std::string negative = load_error(with("manifold = true\nmanifold_recycle = -1e-6"));
  EXPECT_EQ(negative.rfind("case.toml:18: contact.manifold_recycle: must be a travel", 0), 0u) << negative;
  const std::string large = load_error(with("manifold = true\nmanifold_recycle = 0.01"));
  EXPECT_EQ(large.rfind("case.toml:18: contact.manifold_recycle", 0), 0u) << large;
  const std::string no_manifold = load_error(with("manifold_recycle = 1e-6"));
  EXPECT_NE(no_manifold.find("contact.manifold_recycle: needs contact.manifold = true"), std::string::npos)
      << no_manifold;
  const std::string no_reuse = load_error(with("manifold = true\nnarrow_phase_reuse = false\nmanifold_recycle = 1e-6"));
  EXPECT_NE(no_reuse.find("contact.manifold_recycle: needs"), std::string::npos) << no_reuse;
  const std::string both = load_error(with("manifold = true\nmanifold_refit = 0.1\nmanifold_recycle = 1e-6"));
  EXPECT_NE(both.find("contact.manifold_recycle: excludes contact.manifold_refit"), std::string::npos) << both;
  EXPECT_EQ(load_error(with("manifold = true\nmanifold_recycle = 1e-6")), "");
}

// Manifold contacts with reuse recycle their points for 10 um unless told otherwise; without
// manifolds, without reuse or with the refit they do not, and no error is raised for a default.
TEST(ScenarioDefaults, RecycleMarginFollowsTheManifoldAndReuse) {
  auto recycle = [](const std::string& lines) {
    io::ScenarioFile f = io::ScenarioFile::from_string(replace(kValid, "friction = 0.5", "friction = 0.5\n" + lines),
                                                       "case.toml");
    return load_scenario(f).world->settings().manifold_recycle;
  };
  EXPECT_EQ(recycle("manifold = true"), kDefaultManifoldRecycle);
  EXPECT_EQ(recycle("manifold = true\nmanifold_recycle = 0"), 0.0);
  EXPECT_EQ(recycle("manifold = true\nmanifold_recycle = 2e-6"), 2e-6);
  EXPECT_EQ(recycle(""), 0.0);
  EXPECT_EQ(recycle("manifold = true\nnarrow_phase_reuse = false"), 0.0);
  EXPECT_EQ(recycle("manifold = true\nmanifold_refit = 0.1"), 0.0);
}

// A key the reader knows but the chosen contact models do not read is said to be so, with why,
// rather than reported as unknown.
TEST(ScenarioErrors, KnownKeysTheModelsDoNotReadAreNamedAsSuch) {
  const std::string speed = load_error(replace(kValid, "friction = 0.5", "friction = 0.5\nimpact_speed = 2.0"));
  EXPECT_NE(speed.find("case.toml:17: contact.impact_speed: not read: a linear spring reads it only beside max_overlap"),
            std::string::npos)
      << speed;
  const std::string modulus = load_error(kValid, {"contact.youngs_modulus=1e9"});
  EXPECT_NE(modulus.find("contact.youngs_modulus: not read: read by normal = \"hertz\" and tangential = \"mindlin\" only"),
            std::string::npos)
      << modulus;
  const std::string formula = load_error(
      replace(kValid, "normal_restitution = 0.5", "normal_damping_rate = 50\nrestitution_damping = \"eq11\""));
  EXPECT_NE(formula.find("case.toml:16: contact.restitution_damping: not read: it says how normal_restitution becomes a "
                         "dashpot, and this contact gives normal_damping_rate instead"),
            std::string::npos)
      << formula;
  // Read by the models that use them, the same keys load.
  EXPECT_EQ(load_error(replace(kValid, "normal_stiffness = 1e4", "normal = \"hertz\"\nyoungs_modulus = 1e7\n"
                                                                  "poisson_ratio = 0.3\nimpact_speed = 1.0")),
            "");
}

TEST(ScenarioErrors, NegativeStiffness) {
  const std::string e = load_error(replace(kValid, "normal_stiffness = 1e4", "normal_stiffness = -1e4"));
  EXPECT_EQ(e.rfind("case.toml:14: contact.normal_stiffness: must be positive", 0), 0u) << e;
}

// run.processors: whole numbers of ranks along each axis.
TEST(ScenarioErrors, ProcessorsInWholeNumbers) {
  EXPECT_EQ(load_error(kValid, {"run.processors=[1, 1, 4]"}), "");
  EXPECT_EQ(load_error(kValid, {"run.processors=[2, 2, 1]"}), "");
  const std::string half = load_error(kValid, {"run.processors=[1.5, 1, 1]"});
  EXPECT_NE(half.find("run.processors: counts of ranks must be whole numbers"), std::string::npos) << half;
  const std::string zero = load_error(kValid, {"run.processors=[0, 1, 1]"});
  EXPECT_NE(zero.find("run.processors"), std::string::npos) << zero;
  EXPECT_EQ(load_error(kValid, {"run.balance=\"neighbours\""}), "");
  const std::string timed = load_error(kValid, {"run.balance=\"time\""});
  EXPECT_NE(timed.find("run.balance"), std::string::npos) << timed;
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

// Inputs that the fuzz target (tests/fuzz) found crashing, hanging or reaching undefined
// behaviour; each now stops with an InputError.

TEST(ScenarioErrors, NonAsciiCharacterAfterAValue) {
  // toml++ 3.3.0 reached __builtin_unreachable on it (see src/talus/io/toml_include.h).
  const std::string e = load_error(replace(kValid, "friction = 0.5", "friction = 0.5\u00b0"));
  EXPECT_EQ(e.rfind("case.toml:16: ", 0), 0u) << e;
}

TEST(ScenarioErrors, MalformedTableHeader) {
  // toml++ 3.3.0 asserted on these before reporting them.
  std::string e = load_error(replace(kValid, "[contact]", "[[[contact]]]"));
  EXPECT_EQ(e.rfind("case.toml:13: ", 0), 0u) << e;
  e = load_error(replace(kValid, "[contact]", "[\fcontact]"));
  EXPECT_EQ(e.rfind("case.toml:13: ", 0), 0u) << e;
}

TEST(ScenarioErrors, InfiniteOrNanNumber) {
  EXPECT_EQ(load_error(replace(kValid, "lo = [-1.0, -1.0, -1.0]", "lo = [-inf, -1.0, -1.0]")),
            "case.toml:6: domain.lo: element 0 must be finite, got -inf");
  EXPECT_EQ(load_error(replace(kValid, "position = [0.1, 0.0, 0.0]", "position = [nan, 0.0, 0.0]")),
            "case.toml:24: particles[1].position: element 0 must be finite, got nan");
  EXPECT_EQ(load_error(replace(kValid, "end_time = 0.01", "end_time = inf")), "case.toml:3: run.end_time: must be finite, got inf");
}

TEST(ScenarioErrors, DomainExtentOverflows) {
  const std::string text = replace(replace(kValid, "lo = [-1.0, -1.0, -1.0]", "lo = [-1e308, -1.0, -1.0]"),
                                   "hi = [1.0, 1.0, 1.0]", "hi = [1e308, 1.0, 1.0]");
  EXPECT_EQ(load_error(text), "case.toml:7: domain.hi: the extent hi - lo overflows a double");
}

TEST(ScenarioErrors, ParticleMassOutOfRange) {
  // A mass that underflows to 0 made World::add_particle throw std::invalid_argument.
  std::string e = load_error(replace(kValid, "radius = 0.01", "radius = 1e-300"));
  EXPECT_EQ(e.rfind("case.toml:10: species.glass.density: gives a particle of mass 0 kg", 0), 0u) << e;
  e = load_error(replace(kValid, "position = [0.1, 0.0, 0.0]", "position = [0.1, 0.0, 0.0]\nradius = 1e-100"));
  EXPECT_EQ(e.rfind("case.toml:25: particles[1].radius: gives a particle of mass", 0), 0u) << e;
}

TEST(ScenarioErrors, CrossArmShorterThanItsCrust) {
  // make_box threw std::invalid_argument: the crust was checked against the width and thickness only.
  EXPECT_EQ(load_error(replace(kValid, "radius = 0.01", "shape = \"cross\"\nlength = 1e-5")),
            "case.toml:9: species.glass.crust: must be smaller than half the arm length, width and thickness");
}

TEST(ScenarioErrors, OverdampedContactGetsAStableTimeStep) {
  // params::collision_time threw std::invalid_argument while the time step was derived. Past
  // critical damping the time scale is the dashpot's, 2 pi m_ij / eta (an explicit step must
  // stay below 2 m_ij / eta), or the undamped half period if shorter.
  io::ScenarioFile f = io::ScenarioFile::from_string(replace(kValid, "normal_restitution = 0.5", "normal_damping = 1e6"), "case.toml");
  const Scenario sc = load_scenario(f);
  const double m = 0.5 * 2500 * 4.0 / 3.0 * 3.14159265358979 * 1e-6;
  EXPECT_NEAR(sc.derived["contact_time"].get<double>(), 2 * 3.14159265358979 * m / 1e6, 1e-3 * 2 * 3.14159265358979 * m / 1e6);
  EXPECT_LT(sc.derived["time_step"].get<double>() * 1e6 / m, 2.0);
}

TEST(ScenarioErrors, ChuteNarrowerThanTwoDiameters) {
  // The rough base's own World threw std::runtime_error while it settled.
  const std::string chute = "[run]\nend_time = 1.0\n\n[chute]\nlength = 2.0\n\n[contact]\nnormal_stiffness = 2e5\n";
  EXPECT_EQ(load_error(chute), "case.toml:5: chute.length: periodic box narrower than two particle diameters plus skin");
}

TEST(ScenarioErrors, ChuteInitialVolumeFractionPastRandomInsertion) {
  // Random sequential insertion jams near 0.38: above 0.35 the filling would stall.
  const std::string chute =
      "[run]\nend_time = 1.0\n\n[chute]\ninitial_volume_fraction = 0.5\n\n[contact]\nnormal_stiffness = 2e5\n";
  EXPECT_EQ(load_error(chute), "case.toml:5: chute.initial_volume_fraction: must be in [0.1, 0.35], got 0.5");
}

TEST(ScenarioErrors, ParticleCountAboveTheLimit) {
  // 1e12 particles were drawn one by one until memory ran out.
  const std::string insert =
      "\n[[insert]]\nspecies = \"glass\"\ncount = 1e12\nregion_lo = [-0.9, -0.9, -0.9]\nregion_hi = [0.9, 0.9, 0.9]\n";
  EXPECT_EQ(load_error(kValid + insert),
            "case.toml:28: insert[0].count: 1000000000002 particles in all, above the limit of 100000000");
  io::ScenarioFile f = io::ScenarioFile::from_string(kValid, "case.toml");
  ScenarioLimits limits;
  limits.max_particles = 1;
  try {
    load_scenario(f, limits);
    ADD_FAILURE() << "no InputError";
  } catch (const io::InputError& e) {
    EXPECT_EQ(std::string(e.what()), "case.toml:18: particles: 2 particles in all, above the limit of 1");
  }
}

TEST(ScenarioErrors, SpeciesNameNoKeyPathCanHold) {
  // "species.glass beads.density" made the key path parser throw std::invalid_argument.
  EXPECT_EQ(load_error(replace(kValid, "[species.glass]", "[species.\"glass beads\"]")),
            "case.toml:9: species.\"glass beads\": a name here must not be empty nor hold spaces, '.', '[', ']' or '='");
}

TEST(ScenarioErrors, InsertionRegionFullDespiteATinyGrowth) {
  // A growth too small to move the top of the region drew positions forever.
  const std::string insert = "\n[[insert]]\nspecies = \"glass\"\ncount = 1000\ngrowth = 1e-300\n"
                             "region_lo = [0.5, 0.5, 0.5]\nregion_hi = [0.6, 0.6, 0.6]\n";
  const std::string e = load_error(kValid + insert);
  EXPECT_EQ(e.rfind("case.toml:28: insert[0].count: insertion region full after", 0), 0u) << e;
}

TEST(ScenarioErrors, OverrideAppliesToTheRun) {
  io::ScenarioFile f = io::ScenarioFile::from_string(kValid, "case.toml");
  f.set_override("run.end_time=0.5");
  EXPECT_DOUBLE_EQ(load_scenario(f).control.end_time, 0.5);
}

}  // namespace
}  // namespace talus
