#include "talus/scenario/dam_break_observer.h"

#include <cmath>
#include <cstdio>

#include "talus/analysis/collapse_contacts.h"
#include "talus/analysis/collapse_json.h"
#include "talus/analysis/collapse_speed.h"
#include "talus/analysis/collapse_summary.h"
#include "talus/analysis/fabric.h"
#include "talus/analysis/force_network.h"
#include "talus/analysis/force_network_pdf.h"
#include "talus/io/csv_writer.h"
#include "talus/io/json_file.h"
#include "talus/io/snapshot_json.h"

namespace talus {

namespace {

using nlohmann::json;

json statistics_json(const collapse::ContactStatistics& s) {
  return {{"particles", s.particles},       {"coordination", s.coordination},
          {"coordination_points", s.coordination_points}, {"contact_points", s.contact_points},
          {"ground_contacts", s.ground},    {"side_wall_contacts", s.side},
          {"gate_contacts", s.gate}};
}

void write_pdf(const std::filesystem::path& path, const ForcePdf& linear, const ForcePdf& log) {
  io::CsvWriter csv(path, {"scale", "force_ratio", "density"});
  for (std::size_t k = 0; k < linear.centres.size(); ++k) csv.row({0.0, linear.centres[k], linear.density[k]});
  for (std::size_t k = 0; k < log.centres.size(); ++k) csv.row({1.0, log.centres[k], log.density[k]});
  csv.close();
}

}  // namespace

std::vector<collapse::Footprint> footprint_templates(const std::vector<CompositeShape>& shapes) {
  std::vector<collapse::Footprint> out(shapes.size());
  for (std::size_t s = 1; s < shapes.size(); ++s)
    for (const CompositePart& part : shapes[s].parts) {
      if (const Box* box = std::get_if<Box>(&part.shape.geometry))
        out[s].boxes.push_back({part.pose.position, box->half_extents, part.pose.orientation});
      else if (const Sphere* sphere = std::get_if<Sphere>(&part.shape.geometry))
        out[s].spheres.push_back({part.pose.position, sphere->radius});
      else  // cylinders and polyhedra are seen as their bounding balls
        out[s].spheres.push_back({part.pose.position, part.shape.bounding_radius});
    }
  return out;
}

std::vector<collapse::Footprint> particle_footprints(const Snapshot& snapshot,
                                                    const std::vector<collapse::Footprint>& templates) {
  std::vector<collapse::Footprint> out(snapshot.particles.size());
  for (std::size_t k = 0; k < snapshot.particles.size(); ++k) {
    const ParticleRecord& p = snapshot.particles[k];
    if (p.fixed) continue;
    if (p.shape == 0)
      out[k].spheres.push_back({p.position, p.radius});
    else
      out[k] = collapse::place_footprint(templates.at(static_cast<std::size_t>(p.shape)), p.position, p.orientation);
  }
  return out;
}

collapse::CollapseSetup DamBreakObserver::collapse_setup() const {
  collapse::CollapseSetup cs;
  cs.initial_length = setup_.gate_position;
  cs.box_length = setup_.box_length;
  cs.width = setup_.width;
  cs.particle_size = particle_size();
  cs.pixel = setup_.pixel;
  return cs;
}

double DamBreakObserver::particle_size() const {
  double r = 0;
  for (const ParticleRecord& p : initial_.particles)
    if (!p.fixed) r = std::max(r, p.radius);
  return 2 * r;
}

void DamBreakObserver::start(World& world, const std::filesystem::path& out) {
  out_ = out;
  templates_ = footprint_templates(world.shapes());
}

bool DamBreakObserver::output(World& world, const Diagnostics& d) {
  if (phase_ == Phase::settling) {
    const double t = world.time();
    if (t >= setup_.settle_min_time && d.max_speed < setup_.static_speed && d.mean_speed < setup_.static_mean_speed)
      open_gate(world, d, true);
    else if (t >= setup_.settle_max_time)
      open_gate(world, d, false);
    return false;
  }
  if (phase_ != Phase::collapsing) return false;
  const Snapshot now = world.snapshot();
  const collapse::MeanSpeeds mean = collapse::mean_speeds(now);
  const collapse::ScaledSpeeds scaled = collapse::scaled_speeds(now, initial_height_, gate_time_);
  speeds_.push_back({world.time() - gate_time_, scaled.time, mean.translational, mean.angular, scaled.translational,
                     scaled.angular});
  if (world.time() - gate_time_ >= setup_.collapse_min_time && d.max_speed < setup_.stop_speed &&
      d.mean_speed < setup_.stop_mean_speed) {
    phase_ = Phase::over;
    return true;
  }
  return false;
}

void DamBreakObserver::open_gate(World& world, const Diagnostics& d, bool static_reached) {
  initial_ = world.snapshot();
  gate_time_ = world.time();
  const std::vector<collapse::Footprint> prints = particle_footprints(initial_, templates_);
  const collapse::CollapseSetup cs = collapse_setup();
  const collapse::CollapseMeasures m = collapse::measure_collapse(initial_, prints, initial_, prints, cs);
  initial_height_ = m.initial_height.mean;

  // Huet et al. 2021, Table III: whole column, half near the gate, quarter near its top.
  const collapse::WallRoles roles{{walls_.floor}, {walls_.side_lo, walls_.side_hi}, {walls_.gate}};
  const collapse::TableThreeRegions regions = collapse::table_three_regions(setup_.gate_position, initial_height_);
  const std::vector<double> forces = contact_force_magnitudes(initial_);
  const ForcePdf linear = force_pdf_linear(forces, 40, 6.0);    // Fig. 15(a)
  const ForcePdf log = force_pdf_log(forces, 40, 1e-3, 20.0);   // Fig. 15(b)
  const FabricHistogram rose = fabric_angle_histogram(initial_, 36);  // Fig. 17
  const PlaneFabric plane = fabric_xz(initial_);
  const collapse::WallLoadShares shares = collapse::wall_load_shares(initial_, roles);

  before_gate_ = {{"static_reached", static_reached},
                  {"time", gate_time_},
                  {"max_speed", d.max_speed},
                  {"mean_speed", d.mean_speed},
                  {"kinetic_energy", d.kinetic()},
                  {"contacts", collapse::contact_statistics(initial_, roles).contact_points / 2},
                  {"whole", statistics_json(collapse::contact_statistics(initial_, roles, regions.whole))},
                  {"near_gate", statistics_json(collapse::contact_statistics(initial_, roles, regions.near_gate))},
                  {"near_gate_top", statistics_json(collapse::contact_statistics(initial_, roles, regions.near_gate_top))},
                  {"mean_contact_force", linear.mean_force},
                  {"fabric_xz", {{"xx", plane.xx}, {"xz", plane.xz}, {"zz", plane.zz},
                                 {"anisotropy", plane.anisotropy}, {"direction", plane.direction}}},
                  {"weight_share", {{"ground", shares.ground}, {"side_walls", shares.side}, {"gate", shares.gate}}}};
  if (!static_reached)
    std::fprintf(stderr, "dam_break: column not static after %.3g s (fastest particle %.3g m/s); opening the gate\n",
                 gate_time_, d.max_speed);

  io::write_json(out_ / "state_before_gate.json", snapshot_to_json(initial_));
  write_pdf(out_ / "force_pdf.csv", linear, log);
  io::CsvWriter fabric(out_ / "fabric.csv", {"theta", "density"});
  for (std::size_t k = 0; k < rose.centres.size(); ++k) fabric.row({rose.centres[k], rose.density[k]});
  fabric.close();
  io::CsvWriter network(out_ / "force_network.csv", {"x_i", "y_i", "z_i", "x_j", "y_j", "z_j", "force", "points"});
  for (const ForceSegment& s : force_network(initial_))
    network.row({s.from.x, s.from.y, s.from.z, s.to.x, s.to.y, s.to.z, s.force, static_cast<double>(s.points)});
  network.close();

  // Huet et al. 2021, Sec. III C: at t = 0 the gate is removed (or starts rising).
  world.walls_mutable()[static_cast<std::size_t>(walls_.gate)].motion.start_time = gate_time_;
  // The checkpoints carry the rule on (WorldState), so a resumed collapse keeps it.
  if (setup_.collapse_tangential) world.set_tangential_model(*setup_.collapse_tangential);
  phase_ = Phase::collapsing;
}

void DamBreakObserver::finish(World& world, const std::filesystem::path& out, nlohmann::json& summary) {
  json db = {{"phase", phase_ == Phase::settling ? "settling" : phase_ == Phase::collapsing ? "collapsing" : "over"},
             {"gate", setup_.gate_pulled ? "pulled" : "removed"}};
  if (setup_.collapse_tangential) db["collapse_tangential"] = tangential_model_name(*setup_.collapse_tangential);
  summary["L0"] = setup_.gate_position;
  summary["W0"] = setup_.width;
  if (phase_ == Phase::settling) {
    summary["dam_break"] = db;
    return;
  }
  const Snapshot final = world.snapshot();
  io::write_json(out / "state_final.json", snapshot_to_json(final));
  summary["dam_break"] = db;
  measure(final, world.time(), out, summary);
}

void DamBreakObserver::measure(const Snapshot& final, double final_time, const std::filesystem::path& out,
                               nlohmann::json& summary) {
  json& db = summary["dam_break"];
  const collapse::CollapseSetup cs = collapse_setup();
  const collapse::CollapseMeasures m =
      collapse::measure_collapse(initial_, particle_footprints(initial_, templates_), final,
                                 particle_footprints(final, templates_), cs);
  // The headline figures at the top of summary.json, the rest under "dam_break".
  const json measures = collapse::collapse_measures_json(m);
  for (const char* key : {"H0", "aspect_ratio", "runout", "runout_low", "runout_high", "final_height", "regime"})
    summary[key] = measures[key];
  summary["final_height_q1"] = measures["final_height_profile"]["q1"];
  summary["final_height_q3"] = measures["final_height_profile"]["q3"];
  summary["com_displacement"] = measures["com_displacement"][0];
  summary["coordination_number"] = before_gate_["whole"]["coordination_points"];
  db["gate_open_time"] = gate_time_;
  db["collapse_duration"] = final_time - gate_time_;
  db["time_scale"] = collapse::collapse_time_scale(m.initial_height.mean, norm(initial_.gravity));
  db["initial_height_q1"] = measures["initial_height_profile"]["q1"];
  db["initial_height_q3"] = measures["initial_height_profile"]["q3"];
  for (const char* key : {"runout_ratio", "runout_ratio_low", "runout_ratio_high", "height_ratio", "height_ratio_low",
                          "height_ratio_high", "com_ratio", "runout_reached_box_end", "displaced_particles",
                          "displaced_fraction"})
    db[key] = measures[key];
  db["com_initial_x"] = measures["com_initial"][0];
  db["particle_size"] = cs.particle_size;
  db["before_gate"] = before_gate_;

  if (!speeds_.empty()) {
    io::CsvWriter speeds(out / "collapse_speeds.csv", {"time", "time_over_tau", "mean_speed", "mean_angular_speed",
                                                      "speed_over_sqrt_gH0", "angular_speed_times_tau"});
    for (const auto& row : speeds_) speeds.row(std::span<const double>(row));
    speeds.close();
  }
  io::CsvWriter runout(out / "runout_profile.csv", {"x", "intensity"});
  for (std::size_t k = 0; k < m.runout.profile.x.size(); ++k) runout.row({m.runout.profile.x[k], m.runout.profile.intensity[k]});
  runout.close();
  io::CsvWriter heights(out / "height_profile.csv", {"y", "initial_height", "final_height"});
  for (std::size_t k = 0; k < m.final_height.y.size(); ++k)
    heights.row({m.final_height.y[k], k < m.initial_height.h.size() ? m.initial_height.h[k] : 0.0, m.final_height.h[k]});
  heights.close();
}

bool DamBreakObserver::reanalyse(const std::filesystem::path& dir, nlohmann::json& summary) {
  const auto before = dir / "state_before_gate.json", after = dir / "state_final.json";
  if (!std::filesystem::exists(before) || !std::filesystem::exists(after) || !summary.contains("dam_break"))
    return false;
  initial_ = snapshot_from_json(io::read_json(before));
  const Snapshot final = snapshot_from_json(io::read_json(after));
  const json& db = summary["dam_break"];
  gate_time_ = db.at("gate_open_time").get<double>();
  before_gate_ = db.at("before_gate");
  speeds_.clear();  // collapse_speeds.csv stays as the run wrote it
  measure(final, gate_time_ + db.at("collapse_duration").get<double>(), dir, summary);
  return true;
}

nlohmann::json DamBreakObserver::state() const {
  return {{"phase", static_cast<int>(phase_)}, {"gate_time", gate_time_}, {"initial_height", initial_height_},
          {"initial", snapshot_to_json(initial_)}, {"before_gate", before_gate_}, {"speeds", speeds_}};
}

void DamBreakObserver::restore(const nlohmann::json& s) {
  phase_ = static_cast<Phase>(s.at("phase").get<int>());
  gate_time_ = s.at("gate_time").get<double>();
  initial_height_ = s.at("initial_height").get<double>();
  initial_ = snapshot_from_json(s.at("initial"));
  before_gate_ = s.at("before_gate");
  speeds_ = s.at("speeds").get<std::vector<std::vector<double>>>();
}

}  // namespace talus
