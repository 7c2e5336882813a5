#pragma once
// Runs a loaded scenario to its end and writes the results folder: a copy of the scenario,
// summary.json and timeseries.csv, all written atomically.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "talus/io/checkpoint_file.h"

#include "talus/scenario/scenario.h"

namespace talus {

struct RunOptions {
  std::filesystem::path out;          ///< results folder
  bool overwrite = false;             ///< allow a non-empty results folder
  bool quiet = false;                 ///< no progress output
  int threads = 0;                    ///< 0: OpenMP default
  std::string scenario_toml;          ///< the final scenario text, copied into the folder
  std::optional<double> checkpoint_interval;  ///< s; replaces run.checkpoint_interval
  // Resume from this checkpoint (read from `restart_source`): the run goes on exactly as the
  // run that wrote it would have, and rewrites the folder's time series from its first row.
  // A checkpoint the run alone holds is consumed: its state moves into the World, not copied.
  std::shared_ptr<io::Checkpoint> restart;
  std::string restart_source;
};

struct RunOutcome {
  std::string stop_reason;  ///< "end_time", "kinetic_energy", "interrupted", "blow_up", an observer's
  double wall_seconds = 0;
  std::string error;                   ///< "blow_up": the one-line message (step, time, particles, quantity)
  std::filesystem::path state_file;    ///< "blow_up": the state's snapshot file in the results folder
};

// The restart checkpoint is let go once restored: options passed by move free its memory (the
// whole state) for the rest of the run.
RunOutcome run_scenario(Scenario& scenario, RunOptions options);

// Set by SIGINT/SIGTERM: the run stops at the end of the current step and writes its results
// and a final checkpoint.
void install_stop_handlers();

}  // namespace talus
