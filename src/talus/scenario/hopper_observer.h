#pragma once
// Hopper discharge onto a floor and the repose angle of the pile it leaves (Huet et al. 2021,
// Appendix B 2, Table II, Fig. 23). The hopper itself is plain [[walls]] (bounded plates); one of
// them, named by hopper.plug, closes the outlet. Phases:
//   filling      the particles fall into the closed hopper; it is full once no particle is faster
//                than static_speed (or settle_max_time has passed);
//   discharging  the plug is removed; the run ends once no particle is faster than stop_speed
//                (after stop_min_time) and the pile is measured (repose_angle.h).
// [hopper] keys: plug, static_speed, settle_min_time, settle_max_time, stop_speed, stop_min_time,
// axis ("x" or "y": the profile direction), floor, bin, fit_low, fit_high, region_lo, region_hi.
#include <string>

#include "talus/analysis/repose_angle.h"
#include "talus/io/scenario_file.h"
#include "talus/scenario/run_observer.h"

namespace talus {

struct HopperSetup {
  std::string plug;              ///< name of the wall that closes the outlet
  double static_speed = 5e-3;    ///< m/s: the filled hopper is static once no particle is faster
  double settle_min_time = 0.05; ///< s, before the static test
  double settle_max_time = 1;    ///< s: the plug is removed then even if particles still move
  double stop_speed = 5e-3;      ///< m/s: the pile is at rest once no particle is faster
  double stop_min_time = 0.1;    ///< s after the plug was removed, before the stop test
  repose::ProfileSettings profile;  ///< bin = 0: twice the largest particle diameter
};

// Reads [hopper]; the region defaults to the whole domain, the floor to its bottom.
HopperSetup read_hopper(const io::ScenarioFile& file, const Vec3& domain_lo, const Vec3& domain_hi);

class HopperObserver : public RunObserver {
 public:
  explicit HopperObserver(const HopperSetup& setup) : setup_(setup) {}
  std::string name() const override { return "hopper"; }
  std::string stop_reason() const override { return "pile_at_rest"; }
  void start(World& world, const std::filesystem::path& out) override;
  bool output(World& world, const Diagnostics& d) override;
  void finish(World& world, const std::filesystem::path& out, nlohmann::json& summary) override;
  nlohmann::json state() const override;
  void restore(const nlohmann::json& state) override;

 private:
  enum class Phase { filling, discharging, over };
  int plug_ = -1;               ///< wall index of the plug
  HopperSetup setup_;
  Phase phase_ = Phase::filling;
  double open_time_ = 0;        ///< s, world time at which the plug was removed
  bool static_reached_ = false; ///< the filled hopper came to rest before the plug was removed
};

}  // namespace talus
