// The talus command line: run, resume, check, analyze, coarse-grain, params; plot, render and fit
// start the Python package talus (python/talus), which also runs the studies of many runs.
#include <CLI/CLI.hpp>

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>

#include "talus/contact/parameter_procedure.h"
#include "talus/io/checkpoint_file.h"
#include "talus/io/input_error.h"
#include "talus/io/json_file.h"
#include "talus/io/scenario_file.h"
#include "talus/scenario/checkpoint_series.h"
#include "talus/scenario/run_checkpoint.h"
#include "talus/parallel/communicator.h"
#include "talus/scenario/run_loop.h"
#include "talus/scenario/saved_coarse_grain.h"
#include "talus/scenario/scenario.h"

namespace {

using namespace talus;

io::ScenarioFile open_scenario(const std::string& path, const std::vector<std::string>& overrides) {
  io::ScenarioFile file = io::ScenarioFile::from_file(path);
  for (const auto& o : overrides) file.set_override(o);
  return file;
}

// How a run starts: afresh, or from a checkpoint (`run --restart`, `resume`).
// What `talus coarse-grain` was asked for.
struct CoarseGrainRequest {
  std::vector<std::string> grid;
  std::string function = "gaussian";
  double width = 0, cutoff = 0;
  double from = 0, to = std::numeric_limits<double>::infinity();
  std::string out;
};

struct RunStart {
  std::string restart;                        ///< checkpoint file; empty: from the scenario's start
  std::optional<double> checkpoint_interval;  ///< s, --checkpoint-interval
};

// The scenario text without the comment lines to_toml() heads it with (they name the source).
std::string scenario_body(const std::string& toml) {
  std::size_t pos = 0;
  while (pos < toml.size() && (toml[pos] == '#' || toml[pos] == '\n')) {
    const std::size_t end = toml.find('\n', pos);
    pos = end == std::string::npos ? toml.size() : end + 1;
  }
  return toml.substr(pos);
}

// Exit statuses: 0 a run that ended as planned, 1 an error, 2 bad input, 3 a run stopped by the
// blow-up guard (scenario/blowup_guard.h), 130 a run stopped by Ctrl-C or SIGTERM.
constexpr int kBlowUpStatus = 3;

// The results folder a checkpoint belongs to (DIR of DIR/checkpoints/NAME.h5), or empty.
std::filesystem::path results_dir_of(const std::filesystem::path& checkpoint) {
  const std::filesystem::path parent = checkpoint.parent_path();
  return parent.filename() == "checkpoints" ? parent.parent_path() : std::filesystem::path();
}

int run_file(io::ScenarioFile& file, const std::string& label, std::string out, bool overwrite, bool quiet, int threads,
             const RunStart& run_start) {
  // Spread over ranks, the run's particles are built by rank 0 alone, which hands them out.
  ScenarioLimits limits;
  limits.particles_on_first_rank = Communicator::world().distributed();
  Scenario scenario = load_scenario(file, limits);
  RunOptions options;
  options.scenario_toml = file.to_toml();
  if (!run_start.restart.empty()) {
    // Rank 0 reads the file whole and checks it; the others read their own share of a state
    // written on as many ranks (and the whole of any other).
    const Communicator& comm = Communicator::world();
    auto checkpoint = std::make_shared<io::Checkpoint>(
        comm.rank() == 0 ? io::read_checkpoint(run_start.restart)
                         : io::read_checkpoint_share(run_start.restart, comm.rank(), comm.size()));
    if (scenario_body(checkpoint->scenario_toml) != scenario_body(options.scenario_toml) &&
        Communicator::world().rank() == 0)
      std::fprintf(stderr, "talus: note: %s differs from the scenario %s was written with; the run goes on with %s\n",
                   label.c_str(), run_start.restart.c_str(), label.c_str());
    const std::filesystem::path home = results_dir_of(run_start.restart);
    if (out.empty() && !home.empty()) out = home.string();
    // Resuming in the checkpoint's own folder replaces its files with the same run's.
    if (!home.empty() && std::filesystem::weakly_canonical(home) == std::filesystem::weakly_canonical(out))
      overwrite = true;
    options.restart = std::move(checkpoint);
    // latest.h5 moves on; the summary names the file it pointed to.
    const std::filesystem::path source = run_start.restart;
    options.restart_source =
        std::filesystem::is_symlink(source) ? (source.parent_path() / std::filesystem::read_symlink(source)).string()
                                            : source.string();
  }
  if (out.empty()) out = "results/" + std::filesystem::path(label).stem().string();
  options.out = out;
  options.overwrite = overwrite;
  options.quiet = quiet;
  options.threads = threads;
  options.checkpoint_interval = run_start.checkpoint_interval;
  install_stop_handlers();
  const RunOutcome outcome = run_scenario(scenario, std::move(options));
  if (outcome.stop_reason == "blow_up") {  // said even with --quiet: the run failed
    std::fprintf(stderr, "talus: error: %s; state in %s\n", outcome.error.c_str(), outcome.state_file.c_str());
    return kBlowUpStatus;
  }
  if (!quiet && Communicator::world().rank() == 0)
    std::fprintf(stderr, "talus: %s after %.1f s of wall time (%s); results in %s\n", outcome.stop_reason.c_str(),
                 outcome.wall_seconds, label.c_str(), out.c_str());
  return outcome.stop_reason == "interrupted" ? 130 : 0;
}

int command_run(const std::string& path, const std::vector<std::string>& overrides, const std::string& out,
                bool overwrite, bool quiet, int threads, const RunStart& run_start) {
  io::ScenarioFile file = open_scenario(path, overrides);
  return run_file(file, path, out, overwrite, quiet, threads, run_start);
}

// `talus resume DIR`: the newest checkpoint of DIR, with the scenario stored in it, into DIR.
int command_resume(const std::string& dir, bool quiet, int threads, std::optional<double> checkpoint_interval) {
  const std::filesystem::path latest = CheckpointSeries::latest(dir);
  if (!std::filesystem::exists(latest))
    throw io::InputError(dir + ": no checkpoint to resume from (" + latest.string() + " is missing)");
  // Only its scenario here: run_file reads the state, and lets it go once restored.
  io::ScenarioFile file =
      io::ScenarioFile::from_string(io::read_checkpoint_scenario(latest), latest.string() + ":/scenario");
  return run_file(file, (std::filesystem::path(dir) / "scenario.toml").string(), dir, true, quiet, threads,
                  {latest.string(), checkpoint_interval});
}

// The folder holding the Python package talus that belongs to this executable: <exe>/python
// in the build tree, <exe>/../lib/python3/dist-packages when installed; empty if neither has it.
std::filesystem::path python_package_parent() {
  std::error_code ec;
  const std::filesystem::path exe_dir = std::filesystem::read_symlink("/proc/self/exe", ec).parent_path();
  if (ec) return {};
  for (const std::filesystem::path dir : {exe_dir / "python", exe_dir / ".." / "lib" / "python3" / "dist-packages"})
    if (std::filesystem::exists(dir / "talus" / "__init__.py")) return dir.lexically_normal();
  return {};
}

// `python3 -m talus ARGS`: figures are drawn by the Python package (matplotlib and VTK from
// Debian), found beside this executable, else on Python's own path. It is built for Debian's
// interpreter. The package never starts this executable for these subcommands.
int run_python(std::vector<std::string> args) {
  const std::filesystem::path package = python_package_parent();
  if (!package.empty()) {
    const char* old = std::getenv("PYTHONPATH");
    const std::string path = package.string() + (old && *old ? ":" + std::string(old) : "");
    setenv("PYTHONPATH", path.c_str(), 1);
  }
  args.insert(args.begin(), {"/usr/bin/python3", "-m", "talus"});
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::fflush(stdout);
  execv(argv[0], argv.data());
  std::perror("talus: cannot start /usr/bin/python3");
  return 1;
}

// The studies of many runs moved to the Python package: they start this executable, never the
// other way round.
int moved_to_python(const std::string& name) {
  const std::filesystem::path package = python_package_parent();
  std::fprintf(stderr, "talus: '%s' is a command of the Python package now:\n  %s/usr/bin/python3 -m talus %s ...\n",
               name.c_str(), package.empty() ? "" : ("PYTHONPATH=" + package.string() + " ").c_str(), name.c_str());
  return 2;
}

// A checkpoint of the initial state, scaled to the particles still to be poured: contact
// memories grow with the contacts, so this is a floor more than a forecast.
std::size_t expected_checkpoint_bytes(Scenario& scenario, const std::string& toml) {
  const std::size_t now = scenario.world->owned_count();
  std::size_t later = now;
  for (const Pouring& p : scenario.pours) later += p.total() - p.poured();
  const std::size_t bytes = io::checkpoint_image(capture_checkpoint(scenario, LoopState{}, toml, {"time"})).size();
  return now > 0 ? bytes * later / now : bytes;
}

// Measures a finished run again from its files, with the scenario as run plus any overrides.
int command_analyze(const std::filesystem::path& dir, const std::vector<std::string>& overrides) {
  io::ScenarioFile file = open_scenario((dir / "scenario.toml").string(), overrides);
  Scenario scenario = load_scenario(file);
  nlohmann::json summary = io::read_json(dir / "summary.json");
  bool any = false;
  for (auto& o : scenario.observers) any = o->reanalyse(dir, summary) || any;
  if (!any) throw std::runtime_error(dir.string() + ": nothing to analyse (neither dam-break states nor chute profiles)");
  io::write_json(dir / "summary.json", summary);
  std::printf("%s: summary.json updated\n", dir.string().c_str());
  return 0;
}

// `talus coarse-grain DIR`: fields of Weinhart et al. 2012, Sect. 3, from the run's snapshot files.
int command_coarse_grain(const std::filesystem::path& dir, const CoarseGrainRequest& r) {
  const CgGrid grid = parse_cg_grid(r.grid);
  const CgFunction f = r.function == "lucy" ? CgFunction::lucy(r.width, grid.dim())
                                            : CgFunction::gaussian(r.width, grid.dim(), r.cutoff);
  const SavedCoarseGraining cg = coarse_grain_saved(dir, grid, f, r.from, r.to);
  const std::filesystem::path out = r.out.empty() ? dir / "coarse_grained.csv" : std::filesystem::path(r.out);
  write_cg_fields_csv(out, cg.mean);
  std::printf("%s: %d snapshots from t = %g to %g on %d grid points; %.3g s reading, %.3g s coarse graining per snapshot\n",
              out.string().c_str(), cg.snapshots, cg.first_time, cg.last_time, grid.size(),
              cg.read_seconds / cg.snapshots, cg.coarse_grain_seconds / cg.snapshots);
  return 0;
}

int command_check(const std::string& path, const std::vector<std::string>& overrides) {
  io::ScenarioFile file = open_scenario(path, overrides);
  Scenario scenario = load_scenario(file);
  scenario.derived["expected_checkpoint_bytes"] = expected_checkpoint_bytes(scenario, file.to_toml());
  std::cout << path << ": ok\n" << scenario.derived.dump(2) << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Talus: discrete element simulation of granular flows"};
  app.set_version_flag("--version", std::string("talus ") + TALUS_VERSION);
  app.require_subcommand(1);

  std::string path, out;
  std::vector<std::string> overrides;
  bool overwrite = false, quiet = false;
  int threads = 0;
  CLI::App* run = app.add_subcommand("run", "Run a scenario file and write its results folder");
  run->add_option("file", path, "Scenario file (TOML)")->required();
  run->add_option("--out", out, "Results folder (default: results/<scenario name>)");
  run->add_option("--threads", threads, "OpenMP threads (default: all cores)")->check(CLI::PositiveNumber);
  run->add_option("--set", overrides, "Override a scenario value: --set key=value (repeatable)");
  run->add_flag("--overwrite", overwrite, "Write into a non-empty results folder");
  run->add_flag("--quiet", quiet, "No progress output");
  RunStart run_start;
  run->add_option("--restart", run_start.restart, "Go on from a checkpoint (DIR/checkpoints/*.h5), bit for bit")
      ->check(CLI::ExistingFile);
  run->add_option("--checkpoint-interval", run_start.checkpoint_interval,
                  "Simulated seconds between checkpoints (replaces run.checkpoint_interval)")
      ->check(CLI::PositiveNumber);

  std::string resume_dir;
  CLI::App* resume = app.add_subcommand("resume", "Go on with a run from the newest checkpoint of its results folder");
  resume->add_option("dir", resume_dir, "Results folder")->required();
  resume->add_option("--threads", threads, "OpenMP threads (default: all cores)")->check(CLI::PositiveNumber);
  resume->add_option("--checkpoint-interval", run_start.checkpoint_interval,
                     "Simulated seconds between checkpoints (replaces the scenario's)")
      ->check(CLI::PositiveNumber);
  resume->add_flag("--quiet", quiet, "No progress output");

  CLI::App* check = app.add_subcommand("check", "Validate a scenario file and print derived quantities");
  check->add_option("file", path, "Scenario file (TOML)")->required();
  check->add_option("--set", overrides, "Override a scenario value: --set key=value (repeatable)");

  std::string view = "side", picture;
  double render_time = -1;
  CLI::App* analyze = app.add_subcommand("analyze", "Measure a finished run again from its results folder");
  analyze->add_option("dir", path, "Results folder")->required();
  analyze->add_option("--set", overrides, "Override a scenario value, e.g. dam_break.pixel=1e-3");
  CoarseGrainRequest cg;
  CLI::App* coarse = app.add_subcommand("coarse-grain", "Continuum fields from a run's snapshot files (needs run.snapshot_interval)");
  coarse->add_option("dir", path, "Results folder")->required();
  coarse->add_option("--grid", cg.grid, "AXIS=LO:HI:N per resolved axis, e.g. --grid z=0:40:200 (others are averaged)")
      ->required();
  coarse->add_option("--function", cg.function, "gaussian or lucy")->check(CLI::IsMember({"gaussian", "lucy"}));
  coarse->add_option("--width", cg.width, "Gaussian width w, or the Lucy cutoff c (length unit of the run)")
      ->required()->check(CLI::PositiveNumber);
  coarse->add_option("--cutoff", cg.cutoff, "Gaussian cutoff c (default 3 w)")->check(CLI::PositiveNumber);
  coarse->add_option("--from", cg.from, "First snapshot time of the average");
  coarse->add_option("--to", cg.to, "Last snapshot time of the average");
  coarse->add_option("--out", cg.out, "CSV file (default DIR/coarse_grained.csv)");
  CLI::App* render = app.add_subcommand(
      "render", "Draw a results folder's configuration as a PNG (needs run.vtk_interval; python3 -m talus render)");
  render->add_option("dir", path, "Results folder")->required();
  render->add_option("--time", render_time, "Simulated time (s); default: the last frame");
  render->add_option("--view", view, "side (x-z) or top (x-y)")->check(CLI::IsMember({"side", "top"}));
  render->add_option("--out", picture, "PNG file (default: DIR/render_<view>_<time>.png)");
  std::string snapshot_times;
  CLI::App* plot = app.add_subcommand(
      "plot", "Plot a results folder: energies; dam-break, ensemble, sweep, hopper and chute figures (python3 -m talus plot)");
  plot->add_option("dir", path, "Results folder")->required();
  plot->add_option("--snapshot-times", snapshot_times, "Dam-break side snapshots at these times (s after the gate opened, T1,T2,...)");

  CLI::App* fit = app.add_subcommand("fit", "Closure fits of a flow map / h_stop folder (python3 -m talus fit)");
  fit->allow_extras();
  fit->prefix_command();
  // Hidden: the studies that start runs are `python3 -m talus ensemble|sweep|hstop|flowmap`.
  std::vector<CLI::App*> moved;
  for (const char* name : {"ensemble", "sweep", "hstop", "flowmap"}) {
    CLI::App* sub = app.add_subcommand(name, "")->group("");
    sub->allow_extras();
    sub->prefix_command();
    moved.push_back(sub);
  }

  CLI::App* params = app.add_subcommand("params", "Contact parameters from material targets");
  params->require_subcommand(1);
  double mass = 1, v_max = 1, delta_max = 0, e_n = 0.5, e_t = 0, kn = 0, gamma = 0, radius = 0;
  bool per_mass = false;
  CLI::App* huet = params->add_subcommand(
      "huet", "Huet et al. 2021, Eqs. 11-19: k_n, eta_n, t_c (and k_t, eta_t with --et) for two equal spheres");
  huet->add_option("--mass", mass, "Particle mass (kg)")->required()->check(CLI::PositiveNumber);
  huet->add_option("--radius", radius, "Particle radius (m), for k_t and eta_t")->check(CLI::PositiveNumber);
  huet->add_option("--vmax", v_max, "Largest impact speed (m/s)")->required()->check(CLI::PositiveNumber);
  huet->add_option("--max-overlap", delta_max, "Largest overlap at vmax (m)")->required()->check(CLI::PositiveNumber);
  huet->add_option("--en", e_n, "Normal restitution")->required()->check(CLI::Range(1e-6, 0.999999));
  huet->add_option("--et", e_t, "Tangential restitution (Pournin, Eqs. 18-19)")->check(CLI::Range(1e-6, 0.999999));
  CLI::App* weinhart = params->add_subcommand(
      "weinhart", "Weinhart et al. 2012, Eqs. 5-6: t_c and restitution from k_n and gamma_n");
  weinhart->add_option("--kn", kn, "Normal stiffness (N/m)")->required()->check(CLI::PositiveNumber);
  weinhart->add_option("--gamma", gamma, "Normal damping (N s/m, or 1/s with --per-mass)")->required()->check(CLI::NonNegativeNumber);
  weinhart->add_option("--mass", mass, "Particle mass (kg), two equal particles")->check(CLI::PositiveNumber);
  weinhart->add_flag("--per-mass", per_mass, "gamma is per unit reduced mass (Silbert et al. 2001 convention)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    if (*run) return command_run(path, overrides, out, overwrite, quiet, threads, run_start);
    if (*resume) return command_resume(resume_dir, quiet, threads, run_start.checkpoint_interval);
    if (*check) return command_check(path, overrides);
    if (*plot) {
      std::vector<std::string> args = {"plot", path};
      if (!snapshot_times.empty()) args.insert(args.end(), {"--snapshot-times", snapshot_times});
      return run_python(args);
    }
    if (*fit) {
      std::vector<std::string> args = fit->remaining();
      args.insert(args.begin(), "fit");
      return run_python(args);
    }
    for (CLI::App* sub : moved)
      if (*sub) return moved_to_python(sub->get_name());
    if (*analyze) return command_analyze(path, overrides);
    if (*coarse) return command_coarse_grain(path, cg);
    if (*render) {
      std::vector<std::string> args = {"render", path, "--view", view};
      if (render_time >= 0) args.insert(args.end(), {"--time", std::to_string(render_time)});
      if (!picture.empty()) args.insert(args.end(), {"--out", picture});
      return run_python(args);
    }
    if (*huet) {
      const double m = 0.5 * mass;
      const double k = params::normal_stiffness_for_overlap(m, v_max, delta_max, e_n);
      const double eta = params::normal_damping(k, m, e_n);
      const double tc = params::contact_time(k, m, e_n);
      std::printf("normal_stiffness %.6g N/m\nnormal_damping %.6g N s/m\ncontact_time %.6g s\ntime_step_20 %.6g s\n", k, eta,
                  tc, tc / 20);
      if (e_t > 0) {
        if (radius <= 0) throw std::invalid_argument("--et needs --radius");
        const double inertia = 0.4 * mass * radius * radius;
        const auto t = params::pournin_tangential(k, eta, m, radius, inertia, radius, inertia, e_n, e_t);
        std::printf("tangential_stiffness %.6g N/m\ntangential_damping %.6g N s/m\n", t.stiffness, t.damping);
      }
      return 0;
    }
    if (*weinhart) {
      const double m = 0.5 * mass;
      const double eta = per_mass ? gamma * m : gamma;
      std::printf("contact_time %.6g\nrestitution %.6g\ntime_step_50 %.6g\n", params::collision_time(kn, eta, m),
                  params::restitution_from_collision(kn, eta, m), params::collision_time(kn, eta, m) / 50);
      return 0;
    }
  } catch (const io::InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "talus: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
