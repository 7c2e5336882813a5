#include "talus/scenario/run_checkpoint.h"

#include <cmath>

#include "talus/io/input_error.h"
#include "talus/io/json_file.h"

namespace talus {

io::Checkpoint capture_checkpoint(Scenario& sc, const LoopState& loop, const std::string& scenario_toml,
                                  const std::vector<std::string>& columns) {
  io::Checkpoint c;
  c.scenario_toml = scenario_toml;
  c.world = sc.world->capture_state();
  c.timeseries_columns = columns;
  c.timeseries = loop.rows;
  nlohmann::json pours = nlohmann::json::array();
  for (const Pouring& p : sc.pours) pours.push_back(p.state());
  nlohmann::json observers = nlohmann::json::array();
  for (const auto& o : sc.observers) observers.push_back({{"name", o->name()}, {"state", o->state()}});
  c.run = {{"next_output", loop.next_output},
           {"next_frame", loop.next_frame},
           {"next_checkpoint", io::time_or_null(loop.next_checkpoint)},
           {"checkpoint_interval", loop.checkpoint_interval},
           {"vtk_times", loop.vtk_times},
           {"next_snapshot", loop.next_snapshot},
           {"snapshots", loop.snapshots},
           {"particles_left_domain", loop.particles_left_domain},
           {"pours", pours},
           {"observers", observers}};
  return c;
}

LoopState restore_checkpoint(Scenario& sc, io::Checkpoint c, const std::string& source,
                             const std::vector<std::string>& columns, const Communicator* ranks) {
  auto fail = [&](const std::string& what) -> void {
    throw io::InputError(source + ": " + what);
  };
  try {
    if (c.world.walls.size() != sc.world->walls().size())
      fail("checkpoint has " + std::to_string(c.world.walls.size()) + " walls, the scenario " +
           std::to_string(sc.world->walls().size()));
    if (c.timeseries_columns != columns) fail("checkpoint's time-series columns differ from the scenario's");
    const nlohmann::json& pours = c.run.at("pours");
    if (pours.size() != sc.pours.size())
      fail("checkpoint has " + std::to_string(pours.size()) + " pours, the scenario " + std::to_string(sc.pours.size()));
    const nlohmann::json& observers = c.run.at("observers");
    if (observers.size() != sc.observers.size()) fail("checkpoint's run observers differ from the scenario's");
    for (std::size_t k = 0; k < observers.size(); ++k)
      if (observers[k].at("name").get<std::string>() != sc.observers[k]->name())
        fail("checkpoint has observer \"" + observers[k].at("name").get<std::string>() + "\" where the scenario has \"" +
             sc.observers[k]->name() + "\"");

    sc.world->restore_state(std::move(c.world), ranks);
    for (std::size_t k = 0; k < pours.size(); ++k) sc.pours[k].restore(pours[k]);
    for (std::size_t k = 0; k < observers.size(); ++k) sc.observers[k]->restore(observers[k].at("state"));

    LoopState loop;
    loop.next_output = c.run.at("next_output").get<double>();
    loop.next_frame = c.run.at("next_frame").get<double>();
    loop.next_checkpoint = io::null_or_time(c.run.at("next_checkpoint"));
    // Absent from older checkpoints: their cadence is unknown, as if none had been set.
    loop.checkpoint_interval = c.run.value("checkpoint_interval", 0.0);
    loop.vtk_times = c.run.at("vtk_times").get<std::vector<double>>();
    loop.next_snapshot = c.run.value("next_snapshot", 0.0);
    loop.snapshots = c.run.value("snapshots", std::size_t{0});
    loop.rows = std::move(c.timeseries);
    loop.particles_left_domain = c.run.value("particles_left_domain", std::uint64_t{0});  // absent before the guard
    return loop;
  } catch (const io::InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw io::InputError(source + ": checkpoint does not fit the scenario: " + e.what());
  }
}

}  // namespace talus
