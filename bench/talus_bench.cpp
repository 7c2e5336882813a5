// talus-bench: the chute benchmark of the project (Weinhart et al. 2012, Sect. 5 chute, flowing
// state), one line per figure: `METRIC <name> <value> <unit>`.
//
//   talus-bench [--quick] [--cache DIR] [--only chute4k|chute32k]
//               [--steps4k N] [--steps32k N] [--warmup N] [--reps N] [--flow-time T] [--gen-threads N]
//   talus-bench --only crosspile [--crosses N] [--static-only] [--cache DIR]
//   talus-bench --only shapes [--shape NAME] [--shape-count N] [--steps N] [--reps N] [--static-only]
//               [--quick] [--cache DIR] [--gen-threads N]
//   talus-bench --micro [--benchmark_filter=...]     Google Benchmark kernels instead
//
// Cases: chute4k = 20 x 10, H = 20 (4000 flowing on the rough base), chute32k = 40 x 40, H = 20
// (32,000 flowing); both at 24 deg, lambda = 1, Weinhart contact, dt = t_c/50, flowed for 30
// time units (--flow-time) once and cached in DIR (default <dir of this executable>/bench-cache/). --quick
// replaces both by 20 x 10, H = 10 chutes flowed 1 time unit, with small step counts (CI smoke).
// Opt-in cases, each settling piles for minutes before its first run (then cached in DIR):
// crosspile = 2000 crosses of Huet et al. 2021 (bench/cross_pile.h); shapes = 1000 icosahedra,
// 1000 hexapods and 1000 tetrapods (bench/shape_pile_cases.h), each settled for a fixed time
// and timed static and flowing (x+ wall removed) as the cross pile, both states cached, prefix
// shapes_<case>_: --shape picks one case, --steps and --reps (default 500 and 3) the timing,
// --shape-count the bodies per pile, --gen-threads the threads that generate the states; --quick
// there is a smoke run (200 bodies, a tenth of the settling and flow times, 100 steps, one
// repetition).
//
// Definitions:
//  - "particles" are all owned particles, flowing + fixed base: the figure per particle-step
//    divides by that count, as LAMMPS's does (its 32,000 include the frozen base).
//  - X_1t, X_2t: microseconds per particle per step on 1 and 2 OpenMP threads, fastest of
//    --reps repetitions of N steps, after a --warmup (contact memory is not cached). In each
//    repetition 1 and then 2 threads run N steps of the same world, so that both see the same
//    machine: its speed drifts by tens of per cent over a minute. X_speedup_2t = X_1t / X_2t.
//  - X_speedup_2t_paired: the median over the repetitions of the 1-thread over the 2-thread
//    time of the same repetition, which a drift between repetitions does not bias.
//  - X_1t_cpu: as X_1t with the process CPU time instead of wall time: what 1 thread costs
//    when other jobs keep it waiting for a core (compare with loadavg).
//  - contacts_per_particle = 2 contacts / particles, the mean coordination number.
//  - neighbors_per_particle = half-list entries (each pair once, skin included) / particles.
//  - rebuild_interval = timed steps / neighbour-list rebuilds.
//  - share_*: fraction of the 1-thread wall time in each World::timer() phase; "other" is the
//    rest (ghost refresh, force folding, loop overhead); 2t_share_* the same on two threads.
//  - chute32k_bytes_per_particle: peak resident memory (VmHWM) minus resident memory before
//    the world is built, per particle, measured in a fresh process (this executable re-run
//    with --memory-probe) that only loads the 32k world from the cache and runs it on 2
//    threads; the OpenMP pool is started before the baseline. chute32k_peak_rss is that
//    process's whole VmHWM, comparable with LAMMPS's resident size.
//  - loadavg: the 1-minute load average after the timings (2 cores: above ~1 means the
//    2-thread figures competed with other jobs).
//  - threads_identical: 1 if the positions after min(N, 200) steps from the cached state on 1
//    and on 2 threads are bitwise identical.
//  - X_guard_over_step_1t, _2t: one scan of the blow-up guard (world/state_guard.h), which the
//    run loop makes after every batch of at most 64 steps, over one time step, fastest of 20
//    batches each followed by a scan (bench/guard_cost.h); a step pays at most 1/64 of it
//    between outputs (1/25 inside the chute's averaging window, where snapshots end batches).
//  - shapes_<case>_{static,flow}_{1t,2t}: as X_1t, X_2t for one pile state loaded from the cache
//    and warmed up for 2000 steps (the fastest of --reps, after 200 untimed steps); _1t_cpu,
//    _speedup_2t and the profile (_share_*, part-pair tests per particle-step) as crosspile_*;
//    _contacts_per_particle counts contact points (a face contact is up to 4),
//    _touching_per_particle the bodies each body touches. A line per figure,
//    "shapes <case>_<state>_<n>t  us/particle-step = ...", sums them up at the end.
//  - cg_*_over_step: coarse graining one snapshot of the chute4k state (Weinhart et al. 2012,
//    Sect. 3; Gaussian, w = 0.25 d) on a 1D depth grid of 200 points or a 3D grid of 40 x 20 x 40,
//    divided by the cost of one time step, both on one thread; cg_snapshot_over_step is
//    World::snapshot() alone, which the coarse graining needs first.
#include <benchmark/benchmark.h>
#include <omp.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "chute_cg_cost.h"
#include "chute_state.h"
#include "chute_timing.h"
#include "cross_pile.h"
#include "guard_cost.h"
#include "load_average.h"
#include "proc_memory.h"
#include "shape_pile.h"

namespace fs = std::filesystem;
using namespace talus;
using namespace talus::bench;

namespace {

struct Options {
  bool quick = false;
  fs::path cache;
  std::string only;                ///< empty: every case
  std::uint64_t steps4k = 2000, steps32k = 500, warmup = 200;
  int reps = 10;
  double flow_time = 0;            ///< sqrt(d/g), age of the cached flowing state; 0: 30 (1 with --quick)
  int gen_threads = 0;             ///< threads for cache generation; 0: omp_get_max_threads()
  std::string probe;               ///< internal: run the memory probe of this case and exit
  std::size_t crosses = 2000;      ///< crosses in the cross pile (--only crosspile)
  bool static_only = false;        ///< cross pile and shapes: time the static state only
  bool reps_given = false;         ///< --reps was given (the cross pile keeps its own 8 otherwise)
  bool no_reuse = false;           ///< cross pile: contact.narrow_phase_reuse = false (A/B)
  double refit = -1;               ///< cross pile: contact.manifold_refit; negative: the default
  double recycle = -1;             ///< cross pile: contact.manifold_recycle (m); negative: the default
  std::string shape;               ///< --only shapes: one case; empty: all three
  std::size_t shape_count = 0;     ///< bodies per shape pile; 0: 1000 (200 with --quick)
  std::uint64_t shape_steps = 0;   ///< timed steps of a shape pile; 0: 500 (100 with --quick)
};

void usage() {
  std::fprintf(stderr,
               "usage: talus-bench [--quick] [--cache DIR] [--only chute4k|chute32k|crosspile|shapes] [--steps4k N] [--steps32k N]\n"
               "                   [--crosses N] [--static-only] (the cross pile runs only with --only crosspile:\n"
               "                   it settles for minutes; --static-only skips its flowing state; --steps N,\n"
               "                   --reps N; --no-reuse turns narrow-phase reuse off, --refit F sets\n"
               "                   contact.manifold_refit, --recycle M contact.manifold_recycle,\n"
               "                   1e-5 m unless --no-reuse or --refit; 0: every point computed)\n"
               "                   [--shape icosahedra|hexapods|tetrapods] [--shape-count N] [--steps N] (the shape\n"
               "                   piles run only with --only shapes; they settle for minutes before the first run)\n"
               "                   [--warmup N] [--reps N] [--flow-time T] [--gen-threads N]\n"
               "       talus-bench --micro [Google Benchmark flags]\n");
}

Options parse(int argc, char** argv) {
  Options o;
  bool steps4k_set = false, steps32k_set = false, warmup_set = false, reps_set = false;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    auto value = [&]() -> std::string {
      if (k + 1 >= argc) throw std::invalid_argument(a + " needs a value");
      return argv[++k];
    };
    if (a == "--quick") o.quick = true;
    else if (a == "--cache") o.cache = value();
    else if (a == "--only") o.only = value();
    else if (a == "--steps4k") { o.steps4k = std::stoull(value()); steps4k_set = true; }
    else if (a == "--steps32k") { o.steps32k = std::stoull(value()); steps32k_set = true; }
    else if (a == "--warmup") { o.warmup = std::stoull(value()); warmup_set = true; }
    else if (a == "--reps") { o.reps = std::stoi(value()); reps_set = o.reps_given = true; }
    else if (a == "--flow-time") o.flow_time = std::stod(value());
    else if (a == "--gen-threads") o.gen_threads = std::stoi(value());
    else if (a == "--crosses") o.crosses = static_cast<std::size_t>(std::stoul(value()));
    else if (a == "--static-only") o.static_only = true;
    else if (a == "--no-reuse") o.no_reuse = true;
    else if (a == "--refit") o.refit = std::stod(value());
    else if (a == "--recycle") o.recycle = std::stod(value());
    else if (a == "--shape") o.shape = value();
    else if (a == "--shape-count") o.shape_count = static_cast<std::size_t>(std::stoul(value()));
    else if (a == "--steps") o.shape_steps = std::stoull(value());
    else if (a == "--memory-probe") o.probe = value();
    else if (a == "--help" || a == "-h") { usage(); std::exit(0); }
    else throw std::invalid_argument("unknown argument " + a);
  }
  if (!o.only.empty() && o.only != "chute4k" && o.only != "chute32k" && o.only != "crosspile" && o.only != "shapes")
    throw std::invalid_argument("--only takes chute4k, chute32k, crosspile or shapes");
  if (o.reps < 1) throw std::invalid_argument("--reps must be at least 1");
  if (o.only != "shapes" && (!o.shape.empty() || o.shape_count))
    throw std::invalid_argument("--shape and --shape-count go with --only shapes");
  if (o.only != "shapes" && o.only != "crosspile" && o.shape_steps)
    throw std::invalid_argument("--steps goes with --only shapes or crosspile");
  if (o.only != "crosspile" && (o.no_reuse || o.refit >= 0 || o.recycle >= 0))
    throw std::invalid_argument("--no-reuse, --refit and --recycle go with --only crosspile");
  if (o.only == "shapes") {
    if (!reps_set) o.reps = o.quick ? 1 : 3;
    if (o.shape_count == 0) o.shape_count = o.quick ? 200 : 1000;
    if (o.shape_steps == 0) o.shape_steps = o.quick ? 100 : 500;
  }
  if (o.flow_time <= 0) o.flow_time = o.quick ? 1 : 30;
  if (o.gen_threads <= 0) o.gen_threads = omp_get_max_threads();
  if (o.quick) {
    if (!steps4k_set) o.steps4k = 200;
    if (!steps32k_set) o.steps32k = 200;
    if (!warmup_set) o.warmup = 50;
    if (!reps_set) o.reps = 1;
  }
  if (o.cache.empty()) o.cache = fs::read_symlink("/proc/self/exe").parent_path() / "bench-cache";
  return o;
}

std::vector<ChuteCase> cases(const Options& o) {
  std::vector<ChuteCase> all;
  if (o.quick) {
    all.push_back(make_case("chute4k", 20, 10, 10, o.flow_time));
    all.push_back(make_case("chute32k", 20, 10, 10, o.flow_time));
  } else {
    all.push_back(make_case("chute4k", 20, 10, 20, o.flow_time));
    all.push_back(make_case("chute32k", 40, 40, 20, o.flow_time));
  }
  std::vector<ChuteCase> chosen;
  for (const ChuteCase& c : all)
    if (o.only.empty() || o.only == c.name) chosen.push_back(c);
  return chosen;
}

std::uint64_t steps_of(const Options& o, const ChuteCase& c) { return c.name == "chute4k" ? o.steps4k : o.steps32k; }

void metric(const std::string& name, double value, const char* unit) {
  std::printf("METRIC %s %.6g %s\n", name.c_str(), value, unit);
  std::fflush(stdout);
}

// --- peak memory, in a fresh process --------------------------------------------------------

constexpr int kProbeThreads = 2;

// Child side: prints "PROBE <rss before KiB> <VmHWM after KiB> <engine bytes> <particles>".
int memory_probe(const Options& o) {
  Options every = o;
  every.only.clear();
  const std::vector<ChuteCase> all = cases(every);
  const ChuteCase* c = nullptr;
  for (const ChuteCase& k : all)
    if (k.name == o.probe) c = &k;
  if (!c) throw std::invalid_argument("unknown probe case " + o.probe);
  omp_set_num_threads(kProbeThreads);
#pragma omp parallel
  { benchmark::DoNotOptimize(omp_get_thread_num()); }  // start the thread pool before the baseline
  reset_peak_resident();
  const std::size_t before = resident_kib();
  auto world = load_state(*c, cache_path(o.cache, *c));
  world->run(o.warmup + steps_of(o, *c));
  const std::size_t peak = peak_resident_kib();
  std::printf("PROBE %zu %zu %zu %zu\n", before, peak, world->memory_bytes(), world->owned_count());
  return 0;
}

struct ProbeResult {
  std::size_t rss_before_kib = 0, peak_kib = 0, engine_bytes = 0, particles = 0;
};

// Parent side: re-runs this executable with the same arguments and --memory-probe.
ProbeResult run_memory_probe(int argc, char** argv, const std::string& name) {
  std::vector<std::string> args(argv, argv + argc);
  args.push_back("--memory-probe");
  args.push_back(name);
  std::vector<char*> cargs;
  for (std::string& s : args) cargs.push_back(s.data());
  cargs.push_back(nullptr);

  int fd[2];
  if (pipe(fd) != 0) throw std::runtime_error("pipe failed");
  std::fflush(stdout);
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    close(fd[0]);
    dup2(fd[1], STDOUT_FILENO);
    close(fd[1]);
    execv("/proc/self/exe", cargs.data());
    _exit(127);
  }
  close(fd[1]);
  std::string out;
  char buf[256];
  for (ssize_t n; (n = read(fd[0], buf, sizeof buf)) > 0;) out.append(buf, static_cast<std::size_t>(n));
  close(fd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  ProbeResult r;
  const std::size_t at = out.find("PROBE ");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || at == std::string::npos ||
      std::sscanf(out.c_str() + at, "PROBE %zu %zu %zu %zu", &r.rss_before_kib, &r.peak_kib, &r.engine_bytes,
                  &r.particles) != 4)
    throw std::runtime_error("memory probe failed: " + out);
  return r;
}

// --- the benchmark ---------------------------------------------------------------------------

// Median over the repetitions of 1-thread time / 2-thread time within the repetition: the two
// run back to back, so a drift of the machine's speed between repetitions cancels.
double paired_speedup(const TimingResult& one, const TimingResult& two) {
  std::vector<double> ratio;
  for (std::size_t r = 0; r < std::min(one.rep_seconds.size(), two.rep_seconds.size()); ++r)
    ratio.push_back(one.rep_seconds[r] / two.rep_seconds[r]);
  if (ratio.empty()) return 0.0;
  std::sort(ratio.begin(), ratio.end());
  const std::size_t m = ratio.size() / 2;
  return ratio.size() % 2 ? ratio[m] : 0.5 * (ratio[m - 1] + ratio[m]);
}

void run_case(const ChuteCase& c, const Options& o) {
  const fs::path file = cache_path(o.cache, c);
  TimingOptions t;
  t.warmup = o.warmup;
  t.steps = steps_of(o, c);
  t.repetitions = o.reps;
  t.threads = {1, 2};
  const std::vector<TimingResult> timed = time_chute(c, file, t);
  const TimingResult& one = timed[0];
  const TimingResult& two = timed[1];

  const std::string& x = c.name;
  const double n = static_cast<double>(one.particles);
  metric(x + "_particles", n, "count");
  metric(x + "_base_particles", static_cast<double>(one.fixed), "count");
  metric(x + "_1t", one.us_per_particle_step, "us");
  metric(x + "_2t", two.us_per_particle_step, "us");
  metric(x + "_1t_cpu", one.us_cpu, "us");
  metric(x + "_speedup_2t", one.us_per_particle_step / two.us_per_particle_step, "x");
  metric(x + "_speedup_2t_paired", paired_speedup(one, two), "x");
  metric(x + "_contacts_per_particle", 2.0 * static_cast<double>(one.contacts) / n, "count");
  metric(x + "_neighbors_per_particle", static_cast<double>(one.pair_entries) / n, "count");
  metric(x + "_rebuild_interval",
         one.rebuilds ? static_cast<double>(one.steps) / static_cast<double>(one.rebuilds) : 0.0, "steps");
  const char* phase[4] = {"integrate", "neighbors", "pair_forces", "wall_forces"};
  double accounted = 0;
  for (int k = 0; k < 4; ++k) {
    metric(x + "_share_" + phase[k], 100 * one.phase_seconds[k] / one.seconds, "%");
    accounted += one.phase_seconds[k];
  }
  metric(x + "_share_other", 100 * (one.seconds - accounted) / one.seconds, "%");
  // Where the second thread does not help: the same shares on two threads.
  accounted = 0;
  for (int k = 0; k < 4; ++k) {
    metric(x + "_2t_share_" + phase[k], 100 * two.phase_seconds[k] / two.seconds, "%");
    accounted += two.phase_seconds[k];
  }
  metric(x + "_2t_share_other", 100 * (two.seconds - accounted) / two.seconds, "%");
  metric(x + "_mean_speed", one.mean_speed, "sqrt(gd)");
  if (x == "chute32k") {  // the same flowing state under Hertz-Mindlin, one thread
    ContactTable hertz = make_empty_chute_world(c.setup)->contacts();
    for (int a = 0; a < hertz.species(); ++a)
      for (int b = a; b < hertz.species(); ++b) hertz.set_pair(a, b, hertz_mindlin_chute_contact());
    TimingOptions h = t;
    h.threads = {1};
    h.contacts = &hertz;
    const TimingResult hm = time_chute(c, file, h).front();
    metric(x + "_hertz_1t", hm.us_per_particle_step, "us");
    metric(x + "_hertz_over_linear_1t", hm.us_per_particle_step / one.us_per_particle_step, "x");
    metric(x + "_hertz_contacts_per_particle", 2.0 * static_cast<double>(hm.contacts) / n, "count");
  }
  const bool identical = same_on_one_and_two_threads(c, file, std::min<std::uint64_t>(t.steps, 200));
  metric(x + "_threads_identical", identical ? 1 : 0, "bool");
  metric(x + "_loadavg", load_average(), "load");
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc > 1 && std::strcmp(argv[1], "--micro") == 0) {
      argv[1] = argv[0];  // hand the rest to Google Benchmark
      int n = argc - 1;
      benchmark::Initialize(&n, argv + 1);
      if (benchmark::ReportUnrecognizedArguments(n, argv + 1)) return 1;
      benchmark::RunSpecifiedBenchmarks();
      benchmark::Shutdown();
      return 0;
    }
    const Options o = parse(argc, argv);
    if (!o.probe.empty()) return memory_probe(o);

    if (o.only == "crosspile") {
      CrossPileOptions c;
      c.crosses = o.crosses;
      c.cache = o.cache;
      c.static_only = o.static_only;
      c.narrow_phase_reuse = !o.no_reuse;
      if (o.refit >= 0) c.manifold_refit = o.refit;
      // As a scenario (the pile always has manifolds).
      c.manifold_recycle =
          o.recycle >= 0 ? o.recycle : default_manifold_recycle(true, c.narrow_phase_reuse, c.manifold_refit);
      if (o.reps_given) c.reps = o.reps;
      if (o.shape_steps) c.steps = o.shape_steps;
      run_cross_pile(c, [](const char* name, double value, const char* unit) { metric(name, value, unit); });
      return 0;
    }
    if (o.only == "shapes") {
      ShapePileOptions s;
      s.count = o.shape_count;
      s.steps = o.shape_steps;
      s.reps = o.reps;
      s.static_only = o.static_only;
      s.shape = o.shape;
      s.time_scale = o.quick ? 0.1 : 1;
      s.gen_threads = o.gen_threads;
      s.cache = o.cache;
      if (o.quick) metric("quick", 1, "bool");
      run_shape_piles(s, [](const char* name, double value, const char* unit) { metric(name, value, unit); });
      return 0;
    }
    const std::vector<ChuteCase> chosen = cases(o);
    if (o.quick) metric("quick", 1, "bool");
    for (const ChuteCase& c : chosen) {  // generate missing caches first, outside every measurement
      double seconds = 0;
      load_or_generate(c, o.cache, o.gen_threads, &seconds);
      if (seconds > 0) std::fprintf(stderr, "[%s] cache generated in %.0f s\n", c.name.c_str(), seconds);
    }
    for (const ChuteCase& c : chosen) {
      if (c.name == "chute32k") {
        const ProbeResult p = run_memory_probe(argc, argv, c.name);
        const double n = static_cast<double>(p.particles);
        metric("chute32k_bytes_per_particle", 1024.0 * static_cast<double>(p.peak_kib - p.rss_before_kib) / n, "B");
        metric("chute32k_engine_bytes_per_particle", static_cast<double>(p.engine_bytes) / n, "B");
        metric("chute32k_peak_rss", static_cast<double>(p.peak_kib) / 1024.0, "MiB");
      }
      run_case(c, o);
      for (int threads = 1; threads <= 2; ++threads) {
        const GuardCost g = time_state_guard(c, cache_path(o.cache, c), threads, o.quick ? 3 : 20);
        const std::string suffix = threads == 1 ? "_1t" : "_2t";
        metric(c.name + "_guard_over_step" + suffix, g.scan_seconds / g.step_seconds, "x");
        metric(c.name + "_guard_us" + suffix, 1e6 * g.scan_seconds, "us");
      }
      if (c.name == "chute4k") {  // coarse graining of the H = 20 chute against its time step, one thread
        const CgCost cg = time_chute_coarse_graining(c, cache_path(o.cache, c), o.quick ? 1 : 3);
        metric("cg_snapshot_over_step", cg.snapshot_seconds / cg.step_seconds, "x");
        metric("cg_1d_200_over_step", cg.cg_1d_seconds / cg.step_seconds, "x");
        metric("cg_3d_40x20x40_over_step", cg.cg_3d_seconds / cg.step_seconds, "x");
        metric("cg_1d_200_ms", 1e3 * cg.cg_1d_seconds, "ms");
        metric("cg_3d_40x20x40_ms", 1e3 * cg.cg_3d_seconds, "ms");
      }
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "talus-bench: %s\n", e.what());
    usage();
    return 1;
  }
}
