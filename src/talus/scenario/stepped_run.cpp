#include "talus/scenario/stepped_run.h"

#include <algorithm>
#include <limits>
#include <optional>

#include "talus/scenario/batch_steps.h"
#include "talus/scenario/run_checkpoint.h"
#include "talus/scenario/run_summary.h"
#include "talus/scenario/run_timeseries.h"

namespace talus {

namespace {
constexpr double kNever = std::numeric_limits<double>::infinity();
}

SteppedRun::SteppedRun(io::ScenarioFile& file)
    : scenario_(load_scenario(file)), scenario_toml_(file.to_toml()), guard_(scenario_.control.on_leave) {
  if (std::optional<BlowUp> blow_up = guard_.check(world())) throw BlowUpError(std::move(*blow_up));
}

void SteppedRun::restore(const io::Checkpoint& checkpoint, const std::string& source) {
  const LoopState loop =
      restore_checkpoint(scenario_, checkpoint, source, timeseries_columns(world(), scenario_.control.on_leave));
  guard_.set_removed(loop.particles_left_domain);
}

std::uint64_t SteppedRun::run(std::uint64_t steps, double until, const BetweenBatches& between) {
  World& w = world();
  const double dt = w.settings().time_step;
  const double end = until - 0.5 * dt;
  std::uint64_t done = 0;
  while (steps > 0 && w.time() < end) {
    // As the run loop: the batches due are poured first, and a batch ends at the next one.
    for (Pouring& pour : scenario_.pours) pour.pour_due(w);
    double due = end;
    for (const Pouring& pour : scenario_.pours) due = std::min(due, pour.next_time());
    const std::uint64_t batch = std::min(steps, steps_until(w.time(), dt, due));
    w.run(batch);
    steps -= batch;
    done += batch;
    if (std::optional<BlowUp> blow_up = guard_.check(w)) throw BlowUpError(std::move(*blow_up));
    if (between) between();
  }
  return done;
}

void SteppedRun::write_checkpoint(const std::filesystem::path& path) {
  const World& w = world();
  // The schedule of a run that starts here: a row one output interval on, a frame and a
  // snapshot file at once, checkpoints from the restarted run's own interval.
  LoopState loop;
  loop.next_output = w.time() + scenario_.control.output_interval;
  loop.next_frame = w.time();
  loop.next_snapshot = w.time();
  loop.next_checkpoint = kNever;
  loop.particles_left_domain = guard_.removed();
  io::write_checkpoint(path, capture_checkpoint(scenario_, loop, scenario_toml_,
                                                timeseries_columns(w, scenario_.control.on_leave)));
}

// A World not stepped since its set-up changed has no contacts yet: make_ready() finds them,
// which the next step then does not do again (the run goes on unchanged).
nlohmann::json SteppedRun::summary() {
  world().make_ready();
  nlohmann::json s = world_summary(scenario_, world().diagnostics());
  s["particles_left_domain"] = guard_.removed();
  return s;
}

Snapshot SteppedRun::snapshot() {
  world().make_ready();
  return world().snapshot();
}

}  // namespace talus
