// The talus command line: run, check, params, render and plot, and the chute study tools.
#include <CLI/CLI.hpp>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <iostream>

#include "talus/contact/parameter_procedure.h"
#include "talus/io/input_error.h"
#include "talus/io/scenario_file.h"
#include "talus/scenario/run_loop.h"
#include "talus/scenario/scenario.h"

namespace {

using namespace talus;

io::ScenarioFile open_scenario(const std::string& path, const std::vector<std::string>& overrides) {
  io::ScenarioFile file = io::ScenarioFile::from_file(path);
  for (const auto& o : overrides) file.set_override(o);
  return file;
}

int command_run(const std::string& path, const std::vector<std::string>& overrides, std::string out, bool overwrite,
                bool quiet, int threads) {
  io::ScenarioFile file = open_scenario(path, overrides);
  Scenario scenario = load_scenario(file);
  if (out.empty()) out = "results/" + std::filesystem::path(path).stem().string();
  RunOptions options;
  options.out = out;
  options.overwrite = overwrite;
  options.quiet = quiet;
  options.threads = threads;
  options.scenario_toml = file.to_toml();
  install_stop_handlers();
  const RunOutcome outcome = run_scenario(scenario, options);
  if (!quiet)
    std::fprintf(stderr, "talus: %s after %.1f s of wall time (%s); results in %s\n", outcome.stop_reason.c_str(),
                 outcome.wall_seconds, path.c_str(), out.c_str());
  return outcome.stop_reason == "interrupted" ? 130 : 0;
}

// The figures are drawn by the project's matplotlib scripts (Debian python3-matplotlib).
int run_tool(const std::string& script, std::vector<std::string> args) {
  const std::string path = std::string(TALUS_TOOLS_DIR) + "/" + script;
  args.insert(args.begin(), {"/usr/bin/python3", path});
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::fflush(stdout);
  execv(argv[0], argv.data());
  std::perror("talus: cannot start /usr/bin/python3");
  return 1;
}

// The running executable, handed to the study tools that launch runs of their own.
std::string self_path() {
  std::error_code ec;
  const auto p = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::string("talus") : p.string();
}

int command_check(const std::string& path, const std::vector<std::string>& overrides) {
  io::ScenarioFile file = open_scenario(path, overrides);
  Scenario scenario = load_scenario(file);
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

  CLI::App* check = app.add_subcommand("check", "Validate a scenario file and print derived quantities");
  check->add_option("file", path, "Scenario file (TOML)")->required();
  check->add_option("--set", overrides, "Override a scenario value: --set key=value (repeatable)");

  std::string view = "side", picture;
  double render_time = -1;
  CLI::App* render = app.add_subcommand("render", "Draw a results folder's configuration as a PNG (needs run.vtk_interval)");
  render->add_option("dir", path, "Results folder")->required();
  render->add_option("--time", render_time, "Simulated time (s); default: the last frame");
  render->add_option("--view", view, "side (x-z) or top (x-y)")->check(CLI::IsMember({"side", "top"}));
  render->add_option("--out", picture, "PNG file (default: DIR/render_<view>_<time>.png)");
  CLI::App* plot = app.add_subcommand("plot", "Plot a results folder's energies and speeds (DIR/energies.png)");
  plot->add_option("dir", path, "Results folder")->required();

  // The chute study tools (Weinhart et al. 2012, Sects. 6, 8, 9): arguments go to the script.
  CLI::App* hstop = app.add_subcommand("hstop", "h_stop search on a chute scenario (tools/chute_hstop.py: --lambda, --jobs, --out)");
  CLI::App* sweep = app.add_subcommand("sweep", "Flow-state map over lambda, H, theta (tools/chute_sweep.py)");
  CLI::App* fit = app.add_subcommand("fit", "Closure fits of a sweep / h_stop folder (tools/chute_fits.py)");
  for (CLI::App* tool : {hstop, sweep, fit}) {
    tool->allow_extras();
    tool->prefix_command();
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
    if (*run) return command_run(path, overrides, out, overwrite, quiet, threads);
    if (*check) return command_check(path, overrides);
    if (*plot) {
      // A chute study folder (a run with depth profiles, a sweep or an h_stop search) gets its figures too.
      const std::filesystem::path dir(path);
      for (const char* f : {"chute_profile.csv", "sweep_runs.csv", "hstop_runs.csv"})
        if (std::filesystem::exists(dir / f)) return run_tool("plot_chute.py", {path});
      return run_tool("plot_timeseries.py", {path});
    }
    if (*hstop || *sweep) {
      std::vector<std::string> args = (*hstop ? hstop : sweep)->remaining();
      args.insert(args.end(), {"--talus", self_path()});
      return run_tool(*hstop ? "chute_hstop.py" : "chute_sweep.py", args);
    }
    if (*fit) return run_tool("chute_fits.py", fit->remaining());
    if (*render) {
      std::vector<std::string> args = {path, "--view", view};
      if (render_time >= 0) args.insert(args.end(), {"--time", std::to_string(render_time)});
      if (!picture.empty()) args.insert(args.end(), {"--out", picture});
      return run_tool("render.py", args);
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
