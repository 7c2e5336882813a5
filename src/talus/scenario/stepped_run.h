#pragma once
// A scenario run step by step on request, without a results folder: what the Python module's
// Simulation drives. Pours add their batches when due and the blow-up guard checks every batch,
// as in the run loop (run_loop.h), and batches are cut alike (batch_steps.h), so that the same
// steps from the same scenario reach the same state. Study observers (the dam break's phases,
// the hopper's, the chute's statistics) are not called: they belong to a run that writes a
// results folder.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "talus/io/checkpoint_file.h"
#include "talus/io/scenario_file.h"
#include "talus/scenario/blowup_guard.h"
#include "talus/scenario/scenario.h"

namespace talus {

// A state no valid step leads to (BlowUpGuard); what() is BlowUp::message.
class BlowUpError : public std::runtime_error {
 public:
  explicit BlowUpError(BlowUp blow_up) : std::runtime_error(blow_up.message), blow_up_(std::move(blow_up)) {}
  const BlowUp& blow_up() const { return blow_up_; }

 private:
  BlowUp blow_up_;
};

class SteppedRun {
 public:
  // Loads the scenario (load_scenario: overrides must be applied to `file` before). Throws
  // BlowUpError for a set-up no step may start from, as the run loop refuses it.
  explicit SteppedRun(io::ScenarioFile& file);

  // Puts the run into a checkpoint's state (restore_checkpoint); `source` names it in errors.
  void restore(const io::Checkpoint& checkpoint, const std::string& source);

  // Called after every batch of steps (at most kMaxBatchSteps), e.g. to notice Ctrl-C; it may
  // throw, leaving the run after a whole batch.
  using BetweenBatches = std::function<void()>;
  // At most `steps` steps, ending at the first step that comes within half a step of `until`
  // (the run loop's test of its end time; no step if the time is there already). Returns the
  // steps run. Throws BlowUpError when the guard finds a broken state (the run stays in it).
  std::uint64_t run(std::uint64_t steps, double until = std::numeric_limits<double>::infinity(),
                    const BetweenBatches& between = {});

  // The run's state as a checkpoint file that `talus run --restart` and restore() go on from;
  // the time series it carries starts empty.
  void write_checkpoint(const std::filesystem::path& path);
  // summary.json's view of the world now (world_summary) and the particles removed so far.
  nlohmann::json summary();
  // Particles and contacts now, for the analyses (analysis/snapshot.h).
  Snapshot snapshot();

  World& world() { return *scenario_.world; }
  const World& world() const { return *scenario_.world; }
  const Scenario& scenario() const { return scenario_; }
  // The scenario as loaded, overrides applied (what a checkpoint carries).
  const std::string& scenario_toml() const { return scenario_toml_; }

 private:
  Scenario scenario_;
  std::string scenario_toml_;
  BlowUpGuard guard_;
};

}  // namespace talus
