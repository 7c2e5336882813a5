#include "talus/scenario/run_summary.h"

#include <omp.h>

#include "talus/parallel/communicator.h"

namespace talus {

namespace {

nlohmann::json diagnostics_json(const Diagnostics& d) {
  return {{"kinetic_translational", d.kinetic_translational}, {"kinetic_rotational", d.kinetic_rotational},
          {"elastic_normal", d.elastic_normal},               {"elastic_tangential", d.elastic_tangential},
          {"elastic_rolling", d.elastic_rolling},             {"gravitational", d.gravitational},
          {"max_overlap_ratio", d.max_overlap_ratio},         {"max_speed", d.max_speed},
          {"mean_speed", d.mean_speed},                       {"max_angular_speed", d.max_angular_speed}};
}

}  // namespace

nlohmann::json world_summary(const Scenario& sc, const Diagnostics& d) {
  const World& world = *sc.world;
  const Communicator& comm = Communicator::world();
  nlohmann::json summary;
  summary["talus_version"] = TALUS_VERSION;
  summary["final_time"] = world.time();
  summary["steps"] = world.step_count();
  summary["time_step"] = world.settings().time_step;
  summary["particles"] = static_cast<std::uint64_t>(comm.sum(static_cast<double>(world.owned_count())));
  summary["ranks"] = comm.size();
  summary["contacts"] = d.contacts;
  summary["wall_contacts"] = d.wall_contacts;
  summary["energies"] = diagnostics_json(d);
  summary["threads"] = omp_get_max_threads();
  summary["neighbour_rebuilds"] = world.rebuilds();
  if (comm.size() > 1) {
    summary["particles_moved_between_ranks"] = comm.sum(static_cast<double>(world.particles_moved_between_ranks()));
    const RankGrid& grid = world.rank_grid();
    summary["slab_axis"] = std::string(1, "xyz"[grid.slab_axis]);
    summary["processors"] = grid.counts();
    summary["balance"] = grid.balance == RankGrid::Balance::count ? "count" : "neighbours";
  }
  // Where the wall time of rank 0 went, by phase of the step (s); the rest is output,
  // analyses and the run loop.
  nlohmann::json phases = nlohmann::json::object();
  for (int k = 0; k < static_cast<int>(Phase::count); ++k)
    phases[phase_name(static_cast<Phase>(k))] = world.timer().seconds(static_cast<Phase>(k));
  summary["phase_seconds"] = phases;
  summary["derived"] = sc.derived;
  nlohmann::json walls = nlohmann::json::object();
  for (std::size_t w = 0; w < world.walls().size(); ++w) {
    const Vec3 f = world.wall_force(w);
    walls[world.walls()[w].name] = {f.x, f.y, f.z};
  }
  summary["wall_forces"] = walls;
  return summary;
}

}  // namespace talus
