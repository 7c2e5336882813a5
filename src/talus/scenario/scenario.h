#pragma once
// A scenario file turned into a ready World plus what the run loop needs to know.
#include <cstdint>
#include <memory>

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "talus/io/scenario_file.h"
#include "talus/scenario/blowup_guard.h"
#include "talus/scenario/pouring.h"
#include "talus/scenario/run_observer.h"
#include "talus/world/world.h"

namespace talus {

struct RunControl {
  double end_time = 0;                       ///< s
  double output_interval = 0;                ///< s between time-series rows
  std::optional<double> stop_kinetic_energy; ///< J: stop once E_kin falls below, after stop_min_time
  double stop_min_time = 0;                  ///< s
  double vtk_interval = 0;                   ///< s between ParaView frames; 0: none
  double snapshot_interval = 0;              ///< s between snapshot files (io/snapshot_file.h); 0: none
  double checkpoint_interval = 0;            ///< s between checkpoints; 0: only the final one
  std::size_t checkpoint_keep = 3;           ///< checkpoints kept in DIR/checkpoints/
  std::uint64_t seed = 1;
  LeavePolicy on_leave = LeavePolicy::error; ///< domain.on_leave: particles leaving a non-periodic face
  // Under mpirun, the ranks along x, y and z (run.processors); zeros: chosen (RankGrid::choose_counts).
  RankCounts processors{0, 0, 0};
  RankGrid::Balance balance = RankGrid::Balance::count;  ///< what the cuts balance (run.balance)
};

struct Scenario {
  std::unique_ptr<World> world;
  RunControl control;
  std::vector<std::string> species;          ///< names, by species index
  std::vector<std::string> wall_materials;   ///< names, by material index
  std::vector<Pouring> pours;                ///< particles poured while the run goes on
  std::vector<std::unique_ptr<RunObserver>> observers;  ///< study-specific phases and analyses
  nlohmann::json derived;                    ///< contact times, time step, counts: printed by `talus check`
};

// What a scenario may ask for. The default refuses only counts no run could hold: 1e8
// particles already take some 40 GB (400 bytes each). The fuzz target (tests/fuzz) lowers it
// so that every input it tries builds in a moment.
struct ScenarioLimits {
  std::size_t max_particles = 100'000'000;  ///< explicit, inserted, poured, filled and chute particles in all
  // Under mpirun: rank 0 alone keeps the particles it builds, and World::distribute hands them
  // out (WorldSettings::particles_on_first_rank). The checks that read the particles are rank
  // 0's, whose error ends the run on every rank.
  bool particles_on_first_rank = false;
};

// Reads every section, validates it (errors name file, line and key) and builds the World.
// Fails on keys nobody read. Overrides (--set) must be applied to `file` before.
Scenario load_scenario(io::ScenarioFile& file, const ScenarioLimits& limits = {});

}  // namespace talus
