// A short real chute run through the scenario file and the run loop (Weinhart et al. 2012,
// Sects. 5-7): a 10 x 5 box, H = 8, theta = 24 deg, lambda = 1, flowed to t = 40 and depth
// profiles averaged over t in [10, 40] with the paper's Gaussian of width 0.25 every t_c/2
// (Eq. 43; sampling every 5 t_c instead was measured to raise the momentum residual from 1.4 %
// to 8.7 %: contact forces change within a collision).
// What holds exactly is checked tightly (mass, the weight carried by the base); what holds only
// for steady flow is checked with the unsteadiness the run itself measures (its mean
// acceleration) and tolerances from the paper (Sect. 7: 0.5 % lithostatic, 0.4 deg friction).
// The checkpoint state of the observer restores the same results.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "talus/io/scenario_file.h"
#include "talus/scenario/chute_study.h"
#include "talus/scenario/run_loop.h"
#include "talus/scenario/scenario.h"

namespace talus {
namespace {

constexpr char kChute[] = R"(
[run]
end_time = 40.0
output_interval = 0.5
seed = 3

[chute]
length = 10.0
width = 5.0
base_diameter = 1.0
fill_height = 8.0
angle = 24.0

[chute.coarse_graining]
start = 10.0
width = 0.25
z_max = 14.0

[contact]
model = "elastic_spring"
normal_stiffness = 2e5
normal_damping_rate = 50
tangential_stiffness_ratio = 0.2857142857142857
tangential_damping_rate = 50
friction = 0.5
)";

struct ChuteRun {
  nlohmann::json summary;
  std::vector<std::vector<double>> profile;  ///< rows of chute_profile.csv
  std::vector<std::string> columns;
  std::filesystem::path dir;
  double seconds = 0;
  nlohmann::json restored_summary;  ///< finish() of a second observer restored from the first's state

  int col(const std::string& name) const {
    for (std::size_t k = 0; k < columns.size(); ++k)
      if (columns[k] == name) return static_cast<int>(k);
    throw std::runtime_error("no column " + name);
  }
};

ChuteRun chute_run() {
  ChuteRun r;
  r.dir = std::filesystem::path(TALUS_BINARY_DIR) / "test-output" / "chute_study";
  io::ScenarioFile f = io::ScenarioFile::from_string(kChute, "chute_test.toml");
  Scenario sc = load_scenario(f);
  RunOptions opt;
  opt.out = r.dir;
  opt.overwrite = true;
  opt.quiet = true;
  opt.scenario_toml = f.to_toml();
  r.seconds = run_scenario(sc, opt).wall_seconds;
  std::ifstream in(r.dir / "summary.json");
  r.summary = nlohmann::json::parse(in);
  std::ifstream csv(r.dir / "chute_profile.csv");
  std::string line, cell;
  std::getline(csv, line);
  for (std::stringstream head(line); std::getline(head, cell, ',');) r.columns.push_back(cell);
  while (std::getline(csv, line)) {
    std::vector<double> row;
    for (std::stringstream s(line); std::getline(s, cell, ',');) row.push_back(std::stod(cell));
    r.profile.push_back(row);
  }
  // A second observer, restored from the first one's checkpoint state, finishes alike.
  io::ScenarioFile g = io::ScenarioFile::from_string(kChute, "chute_test.toml");
  auto twin = make_chute_observer(read_chute_study(g, sc.derived["contact_time"].get<double>(), 40.0, 8.0, 1.0, 6 / M_PI));
  twin->restore(nlohmann::json::parse(sc.observers.front()->state().dump()));
  std::filesystem::create_directories(r.dir / "restored");
  twin->finish(*sc.world, r.dir / "restored", r.restored_summary);
  return r;
}

// One TEST: ctest runs every TEST in a process of its own, and the run is the expensive part.
TEST(ChuteStudy, ShortRunObeysTheBalances) {
  const ChuteRun r = chute_run();
  {
    SCOPED_TRACE("SummaryHasTheClosureQuantities");
    std::cout << "  chute run: " << r.seconds << " s; " << r.summary.dump() << "\n";
    for (const char* key : {"flow_state", "h", "base", "surface", "mean_velocity", "froude", "mu_macro", "K", "alpha",
                            "bulk_volume_fraction"})
      EXPECT_TRUE(r.summary.contains(key)) << key;
    EXPECT_NE(r.summary["flow_state"], "arrested");  // H = 8 > h_stop(24 deg) = 5.3 (Table 1, Eq. 35)
    // About 400 particles of volume pi/6 on 50 d^2 at volume fraction ~0.57: h ~ 7.3 d.
    EXPECT_NEAR(r.summary["h"].get<double>(), 8 * (M_PI / 6) / 0.57, 1.0);
    EXPECT_GT(r.summary["chute"]["snapshots"].get<int>(), 4000);  // 10 / (t_c / 2)
  }
  {
    SCOPED_TRACE("MassIsConserved");
    // ∫ rho dz over the profile = flowing mass per area: the cut Gaussian integrates to one; the
    // trapezoid rule on w/4 spacing adds ~1e-6 (its jump at the cutoff).
    const int z = r.col("z"), rho = r.col("density");
    double mass = 0;
    for (std::size_t k = 0; k + 1 < r.profile.size(); ++k)
      mass += 0.5 * (r.profile[k][rho] + r.profile[k + 1][rho]) * (r.profile[k + 1][z] - r.profile[k][z]);
    const double expected = r.summary["chute"]["flowing_mass_per_area"].get<double>();
    EXPECT_NEAR(mass, expected, 1e-5 * expected);
    // Eq. 18 for a flow uniform in x, y: d(rho w)/dz = -d rho/dt, which averages out.
    EXPECT_LT(r.summary["chute"]["checks"]["mass_residual"].get<double>(), 0.02);
  }
  {
    SCOPED_TRACE("NormalStressIsLithostatic");
    const auto& c = r.summary["chute"]["checks"];
    // Sect. 7: sigma_zz matches Eq. 41 within 0.5 %. Normal to the base the flow does not
    // accelerate on average, so this holds in the unsteady start-up as well.
    EXPECT_LT(c["lithostatic_error"].get<double>(), 0.005);
    // The base carries the whole weight, exactly in the long-time average. A window samples a
    // base force that fluctuates with every collision: over T = 10, seeds 1-6 gave weight errors
    // of -0.80 % to +0.12 % and lithostatic errors of 0.15-0.84 %; over T = 30, seeds 2-4 gave
    // at most 0.16 % and 0.20 %, so the paper's 0.5 % applies to this window.
    EXPECT_LT(std::abs(c["weight_error"].get<double>()), 0.005);
  }
  {
    SCOPED_TRACE("BasalFrictionBalancesGravityAndAcceleration");
    const auto& c = r.summary["chute"]["checks"];
    // Depth-integrated Eq. 19 down the slope: sigma_xz(b) = (M/A)(g sin(theta) - a), so
    // mu_b = tan(theta) - a / (g cos(theta)); a = 0 in steady flow (Sect. 7: within 0.4 deg).
    const double theta = 24 * M_PI / 180, a = c["mean_acceleration"].get<double>();
    const double expected = std::atan(std::tan(theta) - a / std::cos(theta));
    EXPECT_NEAR(std::atan(c["mu_base"].get<double>()), expected, 0.4 * M_PI / 180);
    // Locally mu(z) = tan(theta) only once steady (Sect. 7: 0.4 deg at T = 100, measured 0.18 deg
    // on a T = 100 run). A T = 10 window was noisy (two realisations differing only in
    // round-off: 0.46 and 1.66 deg); over T = 30 seeds 2-4 gave 0.21-0.29 deg, so 1 deg bounds it.
    EXPECT_LT(c["max_angle_deviation_deg"].get<double>(), 1.0);
  }
  {
    SCOPED_TRACE("MomentumBalanceResidualIsSmall");
    // Fig. 5: the residual of Eq. 44 falls like 1/T, to 2 % of rho g at T = 100. Measured here
    // (rms over the depth): 1.4 % of rho g at T = 10, 1.1-1.3 % for seeds 2-4 at T = 30.
    EXPECT_LT(r.summary["chute"]["checks"]["momentum_residual"].get<double>(), 0.05);
  }
  {
    SCOPED_TRACE("CheckpointStateRestoresTheAverages");
    for (const char* key : {"h", "froude", "mu_macro", "K", "alpha", "flow_state"})
      EXPECT_EQ(r.restored_summary[key], r.summary[key]) << key;
    EXPECT_EQ(r.restored_summary["chute"]["checks"], r.summary["chute"]["checks"]);
  }
}

}  // namespace
}  // namespace talus
