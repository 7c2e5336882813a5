#include "talus/scenario/run_loop.h"

#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <limits>
#include <cstdio>
#include <optional>

#include "talus/io/atomic_file.h"
#include "talus/io/csv_writer.h"
#include "talus/io/json_file.h"
#include "talus/io/results_dir.h"
#include "talus/io/snapshot_file.h"
#include "talus/io/vtk_output.h"
#include "talus/scenario/batch_steps.h"
#include "talus/scenario/blowup_guard.h"
#include "talus/scenario/checkpoint_series.h"
#include "talus/parallel/communicator.h"
#include "talus/scenario/run_checkpoint.h"
#include "talus/scenario/run_summary.h"
#include "talus/scenario/run_timeseries.h"
#include "talus/scenario/spread_run.h"

namespace talus {

namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

volatile std::sig_atomic_t g_stop_requested = 0;
extern "C" void request_stop(int) { g_stop_requested = 1; }

// Rate and ETA count from where this process began: a resumed run starts at its checkpoint's
// step and time, not at zero.
class Progress {
 public:
  Progress(bool quiet, const World& w)
      : quiet_(quiet),
        tty_(isatty(STDERR_FILENO)),
        start_(Clock::now()),
        last_(start_),
        start_step_(w.step_count()),
        start_time_(w.time()) {}
  void update(const World& w, double end_time, bool force = false) {
    if (quiet_) return;
    const auto now = Clock::now();
    const double since = std::chrono::duration<double>(now - last_).count();
    if (!force && since < (tty_ ? 0.5 : 10.0)) return;
    last_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double rate = elapsed > 0 ? static_cast<double>(w.step_count() - start_step_) / elapsed : 0;
    const double fraction = std::min(1.0, w.time() / end_time);
    const double done = w.time() - start_time_;
    const double eta = done > 0 ? elapsed * std::max(0.0, end_time - w.time()) / done : 0;
    // Only rank 0 of a distributed run reports progress: counts over the ranks would need the
    // others to join at times only this process's clock decides.
    if (w.distributed())
      std::fprintf(stderr, "%st = %.6g s (%5.1f %%)  %.0f steps/s  %zu particles on rank 0 of %d  ETA %.0f s%s",
                   tty_ ? "\r" : "", w.time(), 100 * fraction, rate, w.owned_count(), w.communicator().size(), eta,
                   tty_ ? "   " : "\n");
    else
      std::fprintf(stderr, "%st = %.6g s (%5.1f %%)  %.0f steps/s  %zu particles  %zu contacts  ETA %.0f s%s",
                   tty_ ? "\r" : "", w.time(), 100 * fraction, rate, w.owned_count(), w.diagnostics().contacts, eta,
                   tty_ ? "   " : "\n");
    std::fflush(stderr);
  }
  void finish() {
    if (!quiet_ && tty_) std::fputc('\n', stderr);
  }

 private:
  using Clock = std::chrono::steady_clock;
  bool quiet_, tty_;
  Clock::time_point start_, last_;
  std::uint64_t start_step_;
  double start_time_;
};

}  // namespace

void install_stop_handlers() {
  std::signal(SIGINT, request_stop);
  std::signal(SIGTERM, request_stop);
}

RunOutcome run_scenario(Scenario& sc, RunOptions options) {
  // Under mpirun the run is spread over the ranks (World::distribute); every rank runs the loop,
  // and its outputs, which read the whole system, are the same on every rank. Rank 0 writes
  // them to the results folder, the others to a scratch folder removed at the end. Snapshot
  // files only rank 0 writes (the others join in gathering them); VTK frames are written in
  // pieces, one per rank.
  const Communicator& comm = Communicator::world();
  const bool spread = comm.size() > 1;
  const std::filesystem::path results = options.out;  // rank 0's folder, where every rank writes VTK pieces
  RunOptions opt = std::move(options);
  std::optional<ScratchFolder> scratch;
  if (spread && comm.rank() > 0) {
    scratch.emplace(opt.out, comm.rank());
    opt.out = scratch->path();
    opt.overwrite = true;
    opt.quiet = true;
  }
  if (opt.threads > 0) omp_set_num_threads(opt.threads);
  io::prepare_results_dir(opt.out, opt.overwrite);
  io::atomic_write(opt.out / "scenario.toml", opt.scenario_toml);
  World& world = *sc.world;
  const RunControl& run = sc.control;
  const std::vector<std::string> columns = timeseries_columns(world, run.on_leave);
  io::CsvWriter csv(opt.out / "timeseries.csv", columns);
  const auto start = std::chrono::steady_clock::now();

  RunOutcome outcome;
  outcome.stop_reason = "end_time";
  LoopState loop;  // everything of the loop a checkpoint carries
  BlowUpGuard guard(run.on_leave);
  std::optional<BlowUp> blow_up;
  auto record_row = [&](const Diagnostics& d) {
    std::vector<double> row = timeseries_row(world, d);
    if (run.on_leave == LeavePolicy::remove) row.push_back(static_cast<double>(guard.removed()));
    csv.row(std::span<const double>(row));
    loop.rows.insert(loop.rows.end(), row.begin(), row.end());
  };
  std::optional<io::VtkOutput> vtk;
  auto frame_due = [&] {
    if (!vtk || world.time() < loop.next_frame - 0.5 * world.settings().time_step) return;
    if (world.distributed()) {  // each rank writes its piece
      const World::SnapshotPiece piece = world.snapshot_piece();
      const Communicator& ranks = world.communicator();
      vtk->write_frame_piece(piece.snapshot, piece.owned, world.walls(), ranks.rank(), ranks.size(),
                             [&] { ranks.barrier(); });
    } else {
      vtk->write_frame(world.snapshot(), world.walls());
    }
    loop.vtk_times.push_back(world.time());
    loop.next_frame += run.vtk_interval;
  };
  // Every rank writes its pieces into the results folder (created by rank 0 before the
  // collective distribute() that precedes the first piece).
  if (run.vtk_interval > 0) vtk.emplace(results / "vtk", world.shapes());
  // Snapshot files for analyses of saved output (`talus coarse-grain`, `talus analyze`).
  auto snapshot_due = [&] {
    if (run.snapshot_interval <= 0 || world.time() < loop.next_snapshot - 0.5 * world.settings().time_step) return;
    const Snapshot snapshot = world.snapshot_on_first_rank();
    if (comm.rank() == 0) io::write_snapshot_file(opt.out / "snapshots" / io::snapshot_file_name(loop.snapshots), snapshot);
    ++loop.snapshots;
    loop.next_snapshot += run.snapshot_interval;
  };
  if (run.snapshot_interval > 0) std::filesystem::create_directories(opt.out / "snapshots");
  for (auto& o : sc.observers) o->start(world, opt.out);
  double checkpoint_interval = opt.checkpoint_interval.value_or(run.checkpoint_interval);
  CheckpointSeries checkpoints(opt.out, run.checkpoint_keep);
  double checkpoint_seconds = 0;
  auto write_checkpoint = [&] {
    const auto t0 = std::chrono::steady_clock::now();
    loop.particles_left_domain = guard.removed();
    const io::Checkpoint checkpoint = capture_checkpoint(sc, loop, opt.scenario_toml, columns);
    if (checkpoint.world.whole)
      checkpoints.write(checkpoint);
    else
      checkpoints.count_written_elsewhere(checkpoint.world.steps);  // rank 0 writes it
    checkpoint_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  const bool restarted = opt.restart != nullptr;
  if (restarted) {
    io::Checkpoint read = opt.restart.use_count() == 1 ? std::move(*opt.restart) : io::Checkpoint(*opt.restart);
    opt.restart.reset();
    loop = restore_checkpoint(sc, std::move(read), opt.restart_source, columns, spread ? &comm : nullptr);
    guard.set_removed(loop.particles_left_domain);
    for (std::size_t r = 0; r + columns.size() <= loop.rows.size(); r += columns.size())
      csv.row(std::span<const double>(loop.rows.data() + r, columns.size()));
    if (vtk) vtk->resume(loop.vtk_times);
    // --checkpoint-interval starts a new cadence now; the scenario's own interval goes on from the
    // checkpoint's next one; without either the run keeps the interval it was started with,
    // which --checkpoint-interval may have set.
    if (!opt.checkpoint_interval && !(run.checkpoint_interval > 0) && loop.checkpoint_interval > 0)
      checkpoint_interval = loop.checkpoint_interval;
    if (opt.checkpoint_interval || !std::isfinite(loop.next_checkpoint) || checkpoint_interval <= 0)
      loop.next_checkpoint = checkpoint_interval > 0 ? world.time() + checkpoint_interval : kNever;
  }
  // Spread before anything looks at the system: a scenario built under mpirun is on rank 0 alone
  // until then (ScenarioLimits::particles_on_first_rank). A restart on the same ranks is spread
  // already.
  if (spread && !world.distributed()) world.distribute(comm, run.processors);
  if (spread) world.balance_ranks_by(run.balance);
  if (!restarted) {
    blow_up = guard.check(world);  // set up broken (say, a particle launched at 1e200 m/s): no step runs
    if (!blow_up) record_row(world.diagnostics());
    loop.next_frame = world.time();
    if (!blow_up) frame_due();
    loop.next_snapshot = world.time();
    if (!blow_up) snapshot_due();
    loop.next_output = world.time() + run.output_interval;
    loop.next_checkpoint = checkpoint_interval > 0 ? world.time() + checkpoint_interval : kNever;
  }
  loop.checkpoint_interval = checkpoint_interval;
  Progress progress(opt.quiet, world);  // after the restart: it counts from the checkpoint's step
  const std::uint64_t first_step = world.step_count();
  const double dt = world.settings().time_step;
  // Each batch ends at the first step where something below is due, as the loop's own tests
  // decide it (batch_steps.h).
  const auto batch_steps = [&] {
    double due = std::min({run.end_time, loop.next_output, loop.next_checkpoint}) - 0.5 * dt;
    if (vtk) due = std::min(due, loop.next_frame - 0.5 * dt);
    if (run.snapshot_interval > 0) due = std::min(due, loop.next_snapshot - 0.5 * dt);
    for (const Pouring& pour : sc.pours) due = std::min(due, pour.next_time());
    for (const auto& o : sc.observers) due = std::min(due, o->next_step_event(world));
    return steps_until(world.time(), dt, due);
  };
  while (!blow_up && world.time() < run.end_time - 0.5 * dt) {
    for (Pouring& pour : sc.pours) pour.pour_due(world);
    world.run(batch_steps());
    // Before anything reads the state: observers, outputs and checkpoints see only sound ones.
    blow_up = guard.check(world);
    if (blow_up) break;
    for (auto& o : sc.observers) o->after_step(world);
    if (world.time() >= loop.next_output - 0.5 * dt) {
      loop.next_output += run.output_interval;
      const Diagnostics d = world.diagnostics();
      record_row(d);
      if (run.stop_kinetic_energy && world.time() >= run.stop_min_time && d.kinetic() < *run.stop_kinetic_energy) {
        outcome.stop_reason = "kinetic_energy";
        break;
      }
      bool stop = false;
      for (auto& o : sc.observers)
        if (!stop && o->output(world, d)) {
          outcome.stop_reason = o->stop_reason();
          stop = true;
        }
      if (stop) break;
    }
    frame_due();
    snapshot_due();
    if (world.time() >= loop.next_checkpoint - 0.5 * dt) {
      loop.next_checkpoint += checkpoint_interval;
      write_checkpoint();
    }
    if (g_stop_requested) {
      outcome.stop_reason = "interrupted";
      break;
    }
    progress.update(world, run.end_time);
  }
  progress.update(world, run.end_time, true);
  progress.finish();
  if (blow_up) {
    // The state goes to a snapshot file for the post-mortem, not to a checkpoint: resuming it
    // would only blow up again, and latest.h5 keeps pointing at the last sound state.
    outcome.stop_reason = "blow_up";
    outcome.error = blow_up->message;
    outcome.state_file = opt.out / kBlowUpStateFile;
    io::write_snapshot_file(outcome.state_file, world.snapshot());
  } else if (checkpoints.written() == 0 || checkpoints.last_step() != world.step_count()) {
    // The final checkpoint holds the loop as it stands before the last row, so that a run
    // restarted from it (say with a later end_time) goes on as this one would have.
    write_checkpoint();
  }
  const Diagnostics d = world.diagnostics();
  record_row(d);
  csv.close();
  outcome.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  nlohmann::json summary = world_summary(sc, d);
  summary["stop_reason"] = outcome.stop_reason;
  summary["wall_time"] = outcome.wall_seconds;
  const double steps_run = static_cast<double>(world.step_count() - first_step);
  summary["steps_per_second"] = outcome.wall_seconds > 0 ? steps_run / outcome.wall_seconds : 0.0;
  summary["checkpoints"] = {{"written", checkpoints.written()},
                            {"latest", CheckpointSeries::latest(opt.out).string()},
                            {"last_bytes", checkpoints.last_bytes()},
                            {"wall_time", checkpoint_seconds}};
  if (restarted) summary["restarted_from"] = {{"checkpoint", opt.restart_source}, {"step", first_step}};
  summary["particles_left_domain"] = guard.removed();
  if (blow_up) {
    // No study measures a broken state; the record says what broke, and no NaN or infinity of
    // the final energies is written as a null, which would read as "not measured".
    summary["blow_up"] = blow_up_json(*blow_up);
    io::write_json(opt.out / "summary.json", io::non_finite_as_text(summary));
    return outcome;
  }
  for (auto& o : sc.observers) o->finish(world, opt.out, summary);
  io::write_json(opt.out / "summary.json", summary);
  return outcome;
}

}  // namespace talus
