#include "talus/scenario/hopper_observer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "talus/io/csv_writer.h"

namespace talus {

HopperSetup read_hopper(const io::ScenarioFile& f, const Vec3& domain_lo, const Vec3& domain_hi) {
  HopperSetup s;
  s.plug = f.get<std::string>("hopper.plug");
  bool plug_found = false;  // the plug must be one of the [[walls]] (named as they name themselves)
  for (std::size_t k = 0; k < f.array_size("walls"); ++k) {
    const std::string key = "walls[" + std::to_string(k) + "]";
    plug_found |= f.get_or<std::string>(key + ".name", "wall" + std::to_string(k)) == s.plug;
  }
  if (!plug_found) f.fail("hopper.plug", "no [[walls]] entry has name = \"" + s.plug + "\"");
  s.static_speed = f.get_or<double>("hopper.static_speed", s.static_speed, io::positive);
  s.settle_min_time = f.get_or<double>("hopper.settle_min_time", s.settle_min_time, io::non_negative);
  s.settle_max_time = f.get_or<double>("hopper.settle_max_time", s.settle_max_time, io::positive);
  if (s.settle_max_time < s.settle_min_time) f.fail("hopper.settle_max_time", "must not be below settle_min_time");
  s.stop_speed = f.get_or<double>("hopper.stop_speed", s.stop_speed, io::positive);
  s.stop_min_time = f.get_or<double>("hopper.stop_min_time", s.stop_min_time, io::non_negative);
  repose::ProfileSettings& p = s.profile;
  p.axis = f.get_choice_or("hopper.axis", "x", {"x", "y"}) == "x" ? 0 : 1;
  p.floor = f.get_or<double>("hopper.floor", domain_lo.z);
  p.bin = f.get_or<double>("hopper.bin", 0.0, io::non_negative);
  p.fit_low = f.get_or<double>("hopper.fit_low", p.fit_low, io::in_range(0, 1));
  p.fit_high = f.get_or<double>("hopper.fit_high", p.fit_high, io::in_range(0, 1));
  if (p.fit_high <= p.fit_low) f.fail("hopper.fit_high", "must exceed hopper.fit_low");
  p.region_lo = f.get_or<Vec3>("hopper.region_lo", domain_lo);
  p.region_hi = f.get_or<Vec3>("hopper.region_hi", domain_hi);
  for (int a = 0; a < 3; ++a)
    if (!(p.region_hi[a] > p.region_lo[a])) f.fail("hopper.region_hi", "must exceed hopper.region_lo on every axis");
  return s;
}

void HopperObserver::start(World& world, const std::filesystem::path& /*out*/) {
  const auto& walls = world.walls();
  for (std::size_t w = 0; w < walls.size(); ++w)
    if (walls[w].name == setup_.plug) plug_ = static_cast<int>(w);
  if (plug_ < 0) throw std::runtime_error("hopper: no wall named \"" + setup_.plug + "\" (hopper.plug)");
  if (phase_ != Phase::filling) return;  // restored from a checkpoint: the plug is already set
  // Closed until the observer removes it.
  Wall& plug = world.walls_mutable()[static_cast<std::size_t>(plug_)];
  plug.motion.kind = WallMotion::Kind::removed;
  plug.motion.start_time = std::numeric_limits<double>::infinity();
}

bool HopperObserver::output(World& world, const Diagnostics& d) {
  const double t = world.time();
  if (phase_ == Phase::filling) {
    static_reached_ = t >= setup_.settle_min_time && d.max_speed < setup_.static_speed;
    if (static_reached_ || t >= setup_.settle_max_time) {
      if (!static_reached_)
        std::fprintf(stderr, "hopper: not static after %.3g s (fastest particle %.3g m/s); removing the plug\n", t,
                     d.max_speed);
      open_time_ = t;
      world.walls_mutable()[static_cast<std::size_t>(plug_)].motion.start_time = t;
      phase_ = Phase::discharging;
    }
    return false;
  }
  if (phase_ == Phase::discharging && t - open_time_ >= setup_.stop_min_time && d.max_speed < setup_.stop_speed) {
    phase_ = Phase::over;
    return true;
  }
  return false;
}

void HopperObserver::finish(World& world, const std::filesystem::path& out, nlohmann::json& summary) {
  const Snapshot final = world.snapshot();
  repose::ProfileSettings p = setup_.profile;
  if (p.bin <= 0) {
    double r = 0;
    for (const ParticleRecord& q : final.particles) r = std::max(r, q.radius);
    p.bin = 4 * r;  // two diameters: the surface of one bin is then rarely a hole between two particles
  }
  const repose::ReposeResult r = repose::measure_repose(final, p);
  auto number = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
  summary["repose_angle"] = number(r.angle_deg);
  summary["repose_angle_left"] = number(r.left.angle_deg);
  summary["repose_angle_right"] = number(r.right.angle_deg);
  summary["pile_height"] = r.pile_height;
  summary["hopper"] = {{"phase", phase_ == Phase::filling ? "filling" : phase_ == Phase::discharging ? "discharging" : "over"},
                       {"static_reached", static_reached_},
                       {"plug_removed_time", open_time_},
                       {"discharge_duration", world.time() - open_time_},
                       {"pile_particles", r.particles},
                       {"apex", r.apex},
                       {"bin", p.bin},
                       {"fit_low", p.fit_low},
                       {"fit_high", p.fit_high},
                       {"left_bins", r.left.bins},
                       {"right_bins", r.right.bins},
                       {"left_slope", r.left.slope},
                       {"right_slope", r.right.slope},
                       {"left_intercept", r.left.intercept},
                       {"right_intercept", r.right.intercept}};
  io::CsvWriter profile(out / "pile_profile.csv", {"position", "height"});
  for (std::size_t k = 0; k < r.profile.position.size(); ++k) profile.row({r.profile.position[k], r.profile.height[k]});
  profile.close();
}

nlohmann::json HopperObserver::state() const {
  return {{"phase", static_cast<int>(phase_)}, {"open_time", open_time_}, {"static_reached", static_reached_}};
}

void HopperObserver::restore(const nlohmann::json& s) {
  phase_ = static_cast<Phase>(s.at("phase").get<int>());
  open_time_ = s.at("open_time").get<double>();
  static_reached_ = s.at("static_reached").get<bool>();
}

}  // namespace talus
