// The composed contact law: solved restitutions, the Hertz impact against its closed form,
// a sphere dropped on a wall rebounding with the restitution it was given, and the reader's
// refusals of combinations that cannot work.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "talus/contact/head_on_impact.h"
#include "talus/contact/parameter_procedure.h"
#include "talus/io/input_error.h"
#include "talus/scenario/scenario.h"

namespace talus {
namespace {

constexpr double kPi = std::numbers::pi;

ContactParams hertz_params(double kn, double c_tsuji, bool tsuji = true) {
  ContactParams p;
  p.normal_law = normal_law_index<HertzNormal>();
  p.normal_stiffness = kn;
  p.damping_scaling = tsuji ? DampingScaling::tsuji : DampingScaling::constant;
  p.normal_damping.per_sqrt_reduced_mass = c_tsuji * std::sqrt(kn);
  return p;
}

// Undamped Hertz impact (Johnson 1985, Sect. 11.4): delta_max = (15 m v^2 / (16 E* sqrt(R)))^(2/5)
// and t_c = 2 I delta_max / v with I = int_0^1 dx / sqrt(1 - x^(5/2)) = sqrt(pi) G(7/5) / G(9/10).
TEST(HeadOnImpact, ElasticHertzMatchesTheClosedForm) {
  const double e_star = 1.2e10, radius = 0.004, m = 0.3e-3, v = 2.5;
  const ContactParams p = hertz_params(4.0 / 3.0 * e_star, 0);
  const params::ImpactOutcome o = params::head_on_impact(p, m, radius, v, true);
  const double delta_max = std::pow(15 * m * v * v / (16 * e_star * std::sqrt(radius)), 0.4);
  const double integral = std::sqrt(kPi) * std::tgamma(1.4) / std::tgamma(0.9);
  // RK4 at 1024 steps per time unit: the exit interpolation dominates, ~1e-8 here.
  EXPECT_NEAR(o.duration / (2 * integral * delta_max / v), 1.0, 1e-6);
  EXPECT_NEAR(o.restitution, 1.0, 1e-6);
}

// The clamped linear spring's exit against an independent root search of F(t) = 0 on the
// closed-form trajectory.
TEST(HeadOnImpact, ClampedLinearMatchesTheForceZero) {
  const double m = 0.5, k = 2e5, eta = 25;
  const double gamma = eta / (2 * m), omega = std::sqrt(k / m - gamma * gamma);
  const auto force = [&](double t) {
    const double delta = std::exp(-gamma * t) * std::sin(omega * t) / omega;
    const double rate = std::exp(-gamma * t) * (std::cos(omega * t) - gamma / omega * std::sin(omega * t));
    return k * delta + eta * rate;
  };
  double lo = 0.5 * kPi / omega, hi = kPi / omega;
  for (int it = 0; it < 200; ++it) (force(0.5 * (lo + hi)) > 0 ? lo : hi) = 0.5 * (lo + hi);
  const double t = 0.5 * (lo + hi);
  const double e = -std::exp(-gamma * t) * (std::cos(omega * t) - gamma / omega * std::sin(omega * t));
  ContactParams p;
  p.normal_stiffness = k;
  p.normal_damping.coefficient = eta;
  const params::ImpactOutcome o = params::head_on_impact(p, m, 1, 1, true);
  EXPECT_NEAR(o.restitution, e, 1e-12);
  EXPECT_NEAR(o.duration, t, 1e-12);
  // Unclamped: Huet et al. 2021, Eqs. (11)-(12).
  const params::ImpactOutcome free = params::head_on_impact(p, m, 1, 1, false);
  EXPECT_NEAR(free.restitution, params::restitution(k, eta, m), 1e-12);
  EXPECT_NEAR(free.duration, params::collision_time(k, eta, m), 1e-12);
}

// The solved dashpot gives back the restitution, for every law, with and without the clamp;
// with Tsuji's dashpot the Hertz restitution does not depend on the impact speed.
TEST(HeadOnImpact, SolvedDampingGivesTheRestitution) {
  for (const double e : {0.05, 0.2, 0.45, 0.9, 0.99})
    for (const bool clamp : {true, false}) {
      const double c = params::damping_for_restitution(normal_law_index<LinearNormal>(), clamp, e);
      ContactParams lin;
      lin.normal_stiffness = 3e4;
      lin.normal_damping.per_sqrt_reduced_mass = c * std::sqrt(lin.normal_stiffness);
      EXPECT_NEAR(params::head_on_impact(lin, 0.02, 1, 1, clamp).restitution, e, 1e-10) << e << " " << clamp;

      const double alpha = params::damping_for_restitution(normal_law_index<HertzNormal>(), clamp, e);
      const ContactParams hertz = hertz_params(1e9, alpha);
      for (const double v : {0.1, 1.0, 30.0})
        EXPECT_NEAR(params::head_on_impact(hertz, 2e-3, 5e-3, v, clamp).restitution, e, 2e-6)
            << e << " " << clamp << " at " << v << " m/s";
    }
}

// A sphere thrown at a wall without gravity, through the scenario reader: the measured
// restitution is the one given (the issue's 0.2 that rebounded at 0.33 before).
std::string wall_impact(const std::string& contact) {
  return R"([run]
end_time = 0.02
time_step = 1e-7

[domain]
lo = [-0.1, -0.1, 0.0]
hi = [0.1, 0.1, 0.2]
gravity = [0.0, 0.0, 0.0]

[species.glass]
density = 2500
radius = 0.005

[[walls]]
point = [0.0, 0.0, 0.0]
normal = [0.0, 0.0, 1.0]

[[particles]]
species = "glass"
position = [0.0, 0.0, 0.0051]
velocity = [0.0, 0.0, -1.0]

[contact]
)" + contact;
}

double rebound(const std::string& text) {
  io::ScenarioFile f = io::ScenarioFile::from_string(text, "impact.toml");
  Scenario sc = load_scenario(f);
  World& w = *sc.world;
  bool touched = false;
  for (int k = 0; k < 200000; ++k) {
    w.run(10);
    const bool touching = w.diagnostics().wall_contacts > 0;
    touched = touched || touching;
    if (touched && !touching) break;
  }
  EXPECT_TRUE(touched);
  return w.particles().velocity[0].z;
}

TEST(ContactRestitution, ASphereOnAWallReboundsWithTheGivenRestitution) {
  // Linear: t_c ~ 1.4e-4 s at 1e-7 s per step. Velocity Verlet's error at ~1400 steps per
  // contact is below 1e-4; the tolerance 1e-3 is the issue's bar.
  for (const double e : {0.05, 0.2, 0.4, 0.6}) {  // 0.05: past critical damping when clamped
    const std::string lin = "model = \"memory\"\nnormal_stiffness = 1e4\nnormal_restitution = " + std::to_string(e) + "\n";
    EXPECT_NEAR(rebound(wall_impact(lin)), e, 1e-3) << "linear, clamped, e = " << e;
    const std::string free = "model = \"elastic_spring\"\nnormal_stiffness = 1e4\nnormal_restitution = " + std::to_string(e) + "\n";
    EXPECT_NEAR(rebound(wall_impact(free)), e, 1e-3) << "linear, unclamped, e = " << e;
    const std::string hertz = "normal = \"hertz\"\nyoungs_modulus = 1e7\npoisson_ratio = 0.3\nimpact_speed = 1.0\n"
                              "normal_restitution = " + std::to_string(e) + "\n";
    EXPECT_NEAR(rebound(wall_impact(hertz)), e, 1e-3) << "Hertz, e = " << e;
  }
  // Huet et al. 2021, Eq. (11) taken literally ignores the clamp: e = 0.2 rebounds at 0.325.
  const double literal = rebound(wall_impact("model = \"memory\"\nnormal_stiffness = 1e4\nnormal_restitution = 0.2\n"
                                             "restitution_damping = \"eq11\"\n"));
  const double zeta = -std::log(0.2) / std::sqrt(kPi * kPi + std::log(0.2) * std::log(0.2));
  const double w = std::sqrt(1 - zeta * zeta);
  EXPECT_NEAR(literal, std::exp(-zeta / w * std::atan2(2 * zeta * w, 2 * zeta * zeta - 1)), 1e-3);
  EXPECT_NEAR(literal, 0.325, 2e-3);
}

// What cannot work is refused before anything runs, with FILE:LINE: KEY: message.
std::string load_error(const std::string& text) {
  try {
    io::ScenarioFile f = io::ScenarioFile::from_string(text, "impact.toml");
    load_scenario(f);
  } catch (const io::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ContactModelErrors, RefusedCombinationsNameTheKey) {
  const auto starts = [](const std::string& e, const std::string& prefix) { return e.rfind(prefix, 0) == 0; };
  std::string e = load_error(wall_impact("normal = \"hertz\"\npoisson_ratio = 0.3\nimpact_speed = 1.0\nnormal_restitution = 0.5\n"));
  EXPECT_TRUE(starts(e, "impact.toml:23: contact.youngs_modulus: missing")) << e;
  e = load_error(wall_impact("normal = \"hertz\"\nyoungs_modulus = 1e7\npoisson_ratio = 0.3\nnormal_restitution = 0.5\n"));
  EXPECT_TRUE(starts(e, "impact.toml:23: contact.impact_speed: missing")) << e;
  e = load_error(wall_impact("normal = \"hertz\"\nyoungs_modulus = 1e7\npoisson_ratio = 0.3\nimpact_speed = 1.0\n"
                             "damping = \"viscous\"\nnormal_restitution = 0.5\n"));
  EXPECT_TRUE(starts(e, "impact.toml:29: contact.normal_restitution: with a constant dashpot")) << e;
  e = load_error(wall_impact("normal = \"hertz\"\nnormal_stiffness = 1e4\n"));
  EXPECT_TRUE(starts(e, "impact.toml:25: contact.normal_stiffness: normal = \"hertz\" takes")) << e;
  e = load_error(wall_impact("normal = \"hertzian\"\nnormal_stiffness = 1e4\n"));
  EXPECT_TRUE(starts(e, "impact.toml:24: contact.normal: must be one of")) << e;
  e = load_error(wall_impact("tangential = \"memory\"\nnormal_stiffness = 1e4\nfriction = 0.5\n[contact.wall]\n"
                             "tangential = \"elastic_spring\"\n"));
  EXPECT_TRUE(starts(e, "impact.toml:28: contact.wall.tangential: \"elastic_spring\" keeps the elastic_spring history"))
      << e;
  e = load_error(wall_impact("tangential = \"none\"\nnormal_stiffness = 1e4\nfriction = 0.5\n"));
  EXPECT_TRUE(starts(e, "impact.toml:26: contact.friction: tangential = \"none\" is frictionless")) << e;
  e = load_error(wall_impact("tangential = \"mindlin\"\nnormal_stiffness = 1e4\ntangential_stiffness = 5.0\n"));
  EXPECT_TRUE(starts(e, "impact.toml:26: contact.tangential_stiffness: tangential = \"mindlin\" takes")) << e;
  e = load_error(wall_impact("rolling = \"huet\"\nnormal_stiffness = 1e4\n"));
  EXPECT_TRUE(starts(e, "impact.toml:23: contact.rolling_friction: rolling = \"huet\" needs")) << e;
}

// Shaped bodies take the linear law without rolling resistance: the rest is refused (a box with
// rolling friction used to pass `talus check` and crash the run).
TEST(ContactModelErrors, ShapedBodiesRefuseHertzAndRolling) {
  const std::string box = R"([run]
end_time = 0.01

[domain]
lo = [-0.1, -0.1, 0.0]
hi = [0.1, 0.1, 0.2]

[species.block]
density = 2500
shape = "box"
half_extents = [0.01, 0.01, 0.01]

[[particles]]
species = "block"
position = [0.0, 0.0, 0.05]

[contact]
normal_stiffness = 1e4
normal_restitution = 0.5
friction = 0.5
)";
  std::string e = load_error(box + "rolling_friction = 0.1\n");
  EXPECT_EQ(e.rfind("impact.toml:21: contact.rolling_friction: rolling resistance (Huet et al. 2021, App. A) is for spheres", 0), 0u)
      << e;
  e = load_error(box + "normal = \"hertz\"\n");
  EXPECT_EQ(e.rfind("impact.toml:21: contact.normal: \"hertz\" needs spheres", 0), 0u) << e;
}

}  // namespace
}  // namespace talus
