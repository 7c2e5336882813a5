// The chute study as a RunObserver: energies at every output step for the flow state (Weinhart
// et al. 2012, Sect. 6), snapshots every t_c/2 inside the averaging window coarse-grained into
// depth profiles (Eq. 43), and at the end the profiles, the closure quantities and the balance
// checks (Sect. 7) in chute_profile*.csv and summary.json, and the depth averages of each
// snapshot by blocks of time in chute_series.csv; `talus analyze` redoes the profiles from saved
// snapshot files.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "talus/analysis/cg_fields_json.h"
#include "talus/analysis/cg_fields_sum.h"
#include "talus/analysis/cg_time_average.h"
#include "talus/analysis/chute_depth_summary.h"
#include "talus/analysis/chute_series.h"
#include "talus/analysis/coarse_grain.h"
#include "talus/io/snapshot_file.h"
#include "talus/scenario/chute_profile_csv.h"
#include "talus/scenario/chute_study.h"

namespace talus {
namespace {

// One state of the flow to coarse-grain: the whole system, or (when the run is spread over
// ranks) this rank's piece of it, whose fields and sums the ranks add up to the whole system's,
// so that no rank holds more than its share.
struct FlowSample {
  Snapshot snapshot;
  std::size_t owned = 0;                // the records that are this sample's particles
  const Communicator* ranks = nullptr;  // the ranks whose pieces add up; nullptr: whole

  static FlowSample of(const World& world) {
    World::SnapshotPiece piece = world.snapshot_piece();
    return {std::move(piece.snapshot), piece.owned, world.distributed() ? &world.communicator() : nullptr};
  }
  static FlowSample whole(Snapshot snap) {
    const std::size_t n = snap.particles.size();
    return {std::move(snap), n, nullptr};
  }
  double sum(double x) const { return ranks ? ranks->sum(x) : x; }
  double flowing_mass() const {
    double mass = 0;
    for (std::size_t i = 0; i < owned; ++i)
      if (!snapshot.particles[i].fixed) mass += snapshot.particles[i].mass;
    return sum(mass);
  }
  double area() const {
    return (snapshot.domain_max.x - snapshot.domain_min.x) * (snapshot.domain_max.y - snapshot.domain_min.y);
  }
};

struct WidthAverage {
  CgFunction function;
  CgTimeAverage average;
};

std::string profile_name(std::size_t k, double width) {
  if (k == 0) return "chute_profile.csv";
  char buf[64];
  std::snprintf(buf, sizeof buf, "chute_profile_w%g.csv", width);
  return buf;
}

class ChuteObserver final : public RunObserver {
 public:
  explicit ChuteObserver(const ChuteStudyConfig& c) : c_(c), series_(c.series_interval) {
    if (!c_.coarse_grain) return;
    std::vector<double> widths = {c_.width};
    widths.insert(widths.end(), c_.extra_widths.begin(), c_.extra_widths.end());
    for (double w : widths)
      widths_.push_back({c_.kernel == CgKernel::lucy ? CgFunction::lucy(w, 1) : CgFunction::gaussian(w, 1), {}});
    next_snapshot_ = c_.start;
  }

  std::string name() const override { return "chute"; }
  std::string stop_reason() const override { return "arrested"; }

  double next_step_event(const World& world) const override {
    const double half_step = 0.5 * world.settings().time_step;
    if (!c_.coarse_grain || next_snapshot_ > c_.end + half_step) return std::numeric_limits<double>::infinity();
    return next_snapshot_ - half_step;
  }

  void after_step(World& world) override {
    if (!c_.coarse_grain) return;
    const double half_step = 0.5 * world.settings().time_step;
    if (world.time() < next_snapshot_ - half_step || world.time() > c_.end + half_step) return;
    while (next_snapshot_ <= world.time() + half_step) next_snapshot_ += c_.interval;
    add_sample(FlowSample::of(world));
  }

  bool output(World& world, const Diagnostics& d) override {
    energies_.push_back({world.time(), d.kinetic(), d.elastic()});
    return c_.stop_when_arrested && d.elastic() > 0 && d.kinetic() < c_.criteria.arrest_ratio * d.elastic() &&
           world.time() <= c_.criteria.arrest_time;
  }

  void finish(World& world, const std::filesystem::path& out, nlohmann::json& summary) override {
    const Diagnostics d = world.diagnostics();
    if (energies_.empty() || energies_.back().time < world.time()) energies_.push_back({world.time(), d.kinetic(), d.elastic()});
    const FlowStateResult flow = classify_flow(energies_, c_.criteria);
    nlohmann::json chute = {{"energy_state", to_string(flow.state)},
                            {"energy_ratio_mean", flow.mean_ratio},
                            {"energy_ratio_drift", flow.relative_drift},
                            {"energy_ratio_rms", flow.relative_rms},
                            {"state_window", {flow.window_start, flow.window_end}}};
    chute["arrest_time"] = flow.arrest_time ? nlohmann::json(*flow.arrest_time) : nlohmann::json(nullptr);

    const FlowSample last = FlowSample::of(world);
    // A run that ended before its window (an arrested pile stopped early) is measured on its
    // final state, so the h_stop search still knows the pile's height h.
    if (!widths_.empty() && widths_.front().average.count() == 0) {
      add_sample(last);
      chute["final_state_only"] = true;
    }
    report(flow.state, last, out, summary, chute);
  }

  // Coarse-grains the run again from its saved snapshots (run.snapshot_interval) inside the
  // averaging window, with the [chute.coarse_graining] settings as they are now (a new width,
  // function or window via --set), and rewrites the profiles and the closure quantities. The flow
  // state from the energies is kept from the run.
  bool reanalyse(const std::filesystem::path& dir, nlohmann::json& summary) override {
    if (!c_.coarse_grain || !summary.contains("chute")) return false;
    const std::vector<std::filesystem::path> files = io::snapshot_files(dir);
    if (files.empty())
      throw std::runtime_error(dir.string() + ": no snapshots to coarse-grain (run with run.snapshot_interval > 0)");
    for (WidthAverage& w : widths_) w.average = {};
    series_ = ChuteSeries(c_.series_interval);
    cg_seconds_ = 0;
    FlowSample last;
    const double tolerance = 0.5 * c_.time_step;
    for (const auto& file : files) {
      FlowSample sample = FlowSample::whole(io::read_snapshot_file(file));
      if (sample.snapshot.time >= c_.start - tolerance && sample.snapshot.time <= c_.end + tolerance) add_sample(sample);
      last = std::move(sample);
    }
    nlohmann::json chute = summary["chute"];
    chute.erase("final_state_only");
    if (widths_.front().average.count() == 0) {  // as in finish(): fall back on the final state
      add_sample(last);
      chute["final_state_only"] = true;
    }
    const FlowState energy_state = flow_state_from_string(chute.at("energy_state").get<std::string>());
    report(energy_state, last, dir, summary, chute);
    summary["chute"]["saved_snapshots"] = files.size();
    return true;
  }

  nlohmann::json state() const override {
    nlohmann::json e = nlohmann::json::array();
    for (const EnergySample& s : energies_) e.push_back({s.time, s.kinetic, s.elastic});
    nlohmann::json avg = nlohmann::json::array();
    for (const WidthAverage& w : widths_)
      avg.push_back({{"count", w.average.count()},
                     {"sum", w.average.count() > 0 ? to_json(w.average.sum()) : nlohmann::json(nullptr)}});
    return {{"energies", e},         {"next_snapshot", next_snapshot_}, {"averages", avg},
            {"first", {first_time_, first_px_}}, {"last", {last_time_, last_px_}}, {"cg_seconds", cg_seconds_},
            {"series", series_.state()}};
  }

  void restore(const nlohmann::json& j) override {
    energies_.clear();
    for (const auto& s : j.at("energies")) energies_.push_back({s.at(0).get<double>(), s.at(1).get<double>(), s.at(2).get<double>()});
    next_snapshot_ = j.at("next_snapshot").get<double>();
    const auto& avg = j.at("averages");
    if (avg.size() != widths_.size()) throw std::invalid_argument("chute checkpoint: coarse-graining widths differ");
    for (std::size_t k = 0; k < widths_.size(); ++k) {
      const int count = avg[k].at("count").get<int>();
      widths_[k].average = count > 0 ? CgTimeAverage::from_sum(cg_fields_from_json(avg[k].at("sum")), count) : CgTimeAverage{};
    }
    first_time_ = j.at("first").at(0).get<double>();
    first_px_ = j.at("first").at(1).get<double>();
    last_time_ = j.at("last").at(0).get<double>();
    last_px_ = j.at("last").at(1).get<double>();
    cg_seconds_ = j.at("cg_seconds").get<double>();
    series_ = ChuteSeries(c_.series_interval);
    if (j.contains("series")) series_.restore(j.at("series"));  // checkpoints written before the series had none
    // A restart with a later window (a finished run extended with a new run.end_time and
    // coarse_graining.start) must not keep the samples the earlier window took: they were all taken
    // before the next snapshot was due, so before the window that now begins.
    if (c_.coarse_grain && next_snapshot_ < c_.start - 0.5 * c_.time_step) {
      for (WidthAverage& w : widths_) w.average = {};
      series_ = ChuteSeries(c_.series_interval);
      next_snapshot_ = c_.start;
    }
  }

 private:
  // Coarse-grains one state into every width's average (Eq. 43).
  void add_sample(const FlowSample& sample) {
    const auto t0 = std::chrono::steady_clock::now();
    const Snapshot& snap = sample.snapshot;
    const CgGrid grid = CgGrid::depth(c_.z_min, c_.z_max, c_.points);
    CgFields first;
    for (WidthAverage& w : widths_) {
      CgFields fields = coarse_grain(snap, grid, w.function, sample.owned);
      if (sample.ranks) sum_over_ranks(fields, *sample.ranks);
      w.average.add(fields);
      if (&w == &widths_.front()) first = std::move(fields);
    }
    // Downslope momentum of the flow, for the mean acceleration over the window.
    double px = 0;
    for (std::size_t i = 0; i < sample.owned; ++i)
      if (!snap.particles[i].fixed) px += snap.particles[i].mass * snap.particles[i].velocity.x;
    px = sample.sum(px);
    const double mass = sample.flowing_mass();
    try {
      series_.add(snap.time, summarize_chute_profile(first, snap.gravity, c_.particle_density, c_.diameter,
                                                     mass / sample.area()));
    } catch (const std::invalid_argument&) {
      // A snapshot without a flow surface on the grid (a grain flying off) has no depth averages.
    }
    if (widths_.front().average.count() == 1) {
      first_time_ = snap.time;
      first_px_ = px;
    }
    last_time_ = snap.time;
    last_px_ = px;
    cg_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }

  // The averaged profiles into the results: chute_profile*.csv, the closure quantities in
  // `summary`, the balance checks in `chute` (then summary["chute"]). `sample` is the final
  // state, for the flowing mass. The energy state is refined by the layering the profile shows.
  void report(FlowState state, const FlowSample& sample, const std::filesystem::path& out, nlohmann::json& summary,
              nlohmann::json& chute) const {
    const Snapshot& last = sample.snapshot;
    const double mass = sample.flowing_mass();
    const double area = sample.area();
    chute["flowing_mass_per_area"] = mass / area;
    const int count = widths_.empty() ? 0 : widths_.front().average.count();
    chute["snapshots"] = count;
    if (count > 0) {
      const CgFields profile = widths_.front().average.mean();
      try {
        const ChuteDepthSummary s =
            summarize_chute_profile(profile, last.gravity, c_.particle_density, c_.diameter, mass / area);
        state = refine_with_layering(state, s.layering, c_.criteria);
        const DepthAverages& a = s.averages;
        summary["h"] = a.surface.height();
        summary["base"] = a.surface.base;
        summary["surface"] = a.surface.surface;
        summary["mean_velocity"] = a.velocity;
        summary["froude"] = s.froude;
        summary["mu_macro"] = a.friction;
        summary["K"] = a.stress_ratio;
        summary["alpha"] = a.shape_factor;
        summary["volume_fraction"] = s.volume_fraction;
        summary["bulk_volume_fraction"] =
            s.bulk_volume_fraction ? nlohmann::json(*s.bulk_volume_fraction) : nlohmann::json(nullptr);
        const double accel = last_time_ > first_time_ ? (last_px_ - first_px_) / (mass * (last_time_ - first_time_)) : 0;
        chute["checks"] = {{"mu_base", s.mu_base},
                           {"tan_theta", std::tan(s.angle)},
                           {"max_angle_deviation_deg", s.max_angle_deviation * 180 / M_PI},
                           {"lithostatic_error", s.lithostatic_error},
                           {"weight_error", s.weight_error},
                           {"momentum_residual", s.momentum_residual},
                           {"mass_residual", s.mass_residual},
                           {"mean_acceleration", accel},
                           {"layering", s.layering}};
        chute.erase("profile_error");
      } catch (const std::invalid_argument& e) {
        chute["profile_error"] = e.what();  // e.g. no flow left on the grid
      }
      for (std::size_t k = 0; k < widths_.size(); ++k)
        write_chute_profile_csv(out / profile_name(k, widths_[k].function.width), widths_[k].average.mean(),
                                last.gravity, c_.particle_density);
      ChuteSeries series = series_;
      series.finish();
      series.write_csv(out / "chute_series.csv");
      chute["series_blocks"] = series.rows().size();
      chute["averaging_window"] = {first_time_, last_time_};
      chute["width"] = c_.width;
      chute["coarse_graining_seconds"] = cg_seconds_;
    }
    summary["flow_state"] = to_string(state);
    summary["chute"] = chute;
  }

  ChuteStudyConfig c_;
  std::vector<WidthAverage> widths_;
  std::vector<EnergySample> energies_;
  double next_snapshot_ = 0;
  double first_time_ = 0, first_px_ = 0, last_time_ = 0, last_px_ = 0;
  double cg_seconds_ = 0;
  ChuteSeries series_;
};

}  // namespace

std::unique_ptr<RunObserver> make_chute_observer(const ChuteStudyConfig& config) {
  return std::make_unique<ChuteObserver>(config);
}

}  // namespace talus
