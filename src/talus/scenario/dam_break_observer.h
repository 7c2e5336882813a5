#pragma once
// The phases of a dam-break run and what it measures (Huet et al. 2021, Secs. III-IV):
//   settling   the column falls into place behind the closed gate; it is static once the
//              mean particle speed is below static_mean_speed and the fastest particle is slower
//              than static_speed (or settle_max_time has passed);
//   collapsing the gate opens (t = 0 of the paper); mean speeds are recorded (Figs. 12-13);
//   over       the mean speed is below stop_mean_speed and no particle is faster than
//              stop_speed: the run ends.
// Before the gate opens: coordination and wall contacts (Table III), force PDF (Fig. 15),
// fabric (Figs. 16-17), Janssen shares, the force network (Fig. 14). At the end: runout with
// its error bar, heights with quartiles, centre-of-mass shift, regime (Sec. III C, App. C).
#include <vector>

#include "talus/analysis/collapse_footprint.h"
#include "talus/analysis/collapse_summary.h"
#include "talus/analysis/snapshot.h"
#include "talus/scenario/dam_break.h"
#include "talus/scenario/run_observer.h"

namespace talus {

class DamBreakObserver : public RunObserver {
 public:
  DamBreakObserver(const DamBreakSetup& setup, const DamBreakWalls& walls) : setup_(setup), walls_(walls) {}
  std::string name() const override { return "dam_break"; }
  std::string stop_reason() const override { return "collapse_over"; }
  void start(World& world, const std::filesystem::path& out) override;
  bool output(World& world, const Diagnostics& d) override;
  void finish(World& world, const std::filesystem::path& out, nlohmann::json& summary) override;
  bool reanalyse(const std::filesystem::path& dir, nlohmann::json& summary) override;
  nlohmann::json state() const override;
  void restore(const nlohmann::json& state) override;

 private:
  enum class Phase { settling, collapsing, over };
  void open_gate(World& world, const Diagnostics& d, bool static_reached);
  double particle_size() const;
  collapse::CollapseSetup collapse_setup() const;
  // The end-of-run measurements of a final state, into summary.json and the profile files.
  void measure(const Snapshot& final, double final_time, const std::filesystem::path& out, nlohmann::json& summary);

  DamBreakSetup setup_;
  DamBreakWalls walls_;
  std::filesystem::path out_;
  std::vector<collapse::Footprint> templates_;  ///< per shape index; shape 0 (spheres) is per particle
  Phase phase_ = Phase::settling;
  double gate_time_ = 0;        ///< s, world time at which the gate opened
  double initial_height_ = 0;   ///< m, H0 for the speed scaling
  Snapshot initial_;            ///< the column just before the gate opened
  nlohmann::json before_gate_;  ///< measurements of the column before the gate opened
  std::vector<std::vector<double>> speeds_;  ///< rows of collapse_speeds.csv
};

// Footprints of every particle of a snapshot (boxes and spheres of its shape's parts).
std::vector<collapse::Footprint> particle_footprints(const Snapshot& snapshot,
                                                     const std::vector<collapse::Footprint>& templates);
// Body-frame footprint templates of the World's shapes (index 0, the sphere, stays empty).
std::vector<collapse::Footprint> footprint_templates(const std::vector<CompositeShape>& shapes);

}  // namespace talus
