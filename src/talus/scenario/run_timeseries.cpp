#include "talus/scenario/run_timeseries.h"

namespace talus {

std::vector<std::string> timeseries_columns(const World& world, LeavePolicy on_leave) {
  std::vector<std::string> c = {"time", "step", "kinetic_translational", "kinetic_rotational", "elastic_normal",
                                "elastic_tangential", "elastic_rolling", "gravitational", "kinetic_over_elastic",
                                "contacts", "wall_contacts", "max_overlap_ratio", "max_speed", "mean_speed",
                                "max_angular_speed"};
  for (const Wall& w : world.walls()) {
    c.push_back("force_" + w.name + "_x");
    c.push_back("force_" + w.name + "_y");
    c.push_back("force_" + w.name + "_z");
  }
  if (on_leave == LeavePolicy::remove) c.push_back("particles_left_domain");  // removed so far
  return c;
}

std::vector<double> timeseries_row(const World& world, const Diagnostics& d) {
  std::vector<double> row = {d.time, static_cast<double>(world.step_count()), d.kinetic_translational,
                             d.kinetic_rotational, d.elastic_normal, d.elastic_tangential, d.elastic_rolling,
                             d.gravitational, d.elastic() > 0 ? d.kinetic() / d.elastic() : 0.0,
                             static_cast<double>(d.contacts), static_cast<double>(d.wall_contacts),
                             d.max_overlap_ratio, d.max_speed, d.mean_speed, d.max_angular_speed};
  for (std::size_t w = 0; w < world.walls().size(); ++w) {
    const Vec3 f = world.wall_force(w);
    row.insert(row.end(), {f.x, f.y, f.z});
  }
  return row;
}

}  // namespace talus
