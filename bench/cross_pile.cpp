#include "cross_pile.h"

#include <omp.h>
#include <x86intrin.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <memory>
#include <string>

#include "chute_state.h"
#include "talus/scenario/cross_box.h"
#include "talus/world/composite_stats.h"
#include "talus/world/world.h"

namespace talus::bench {

namespace {

using Clock = std::chrono::steady_clock;
constexpr std::uint32_t kVersion = 1;  // of the generation recipe below: bump when it changes

CrossBoxSetup pile_setup(const CrossPileOptions& o) {
  CrossBoxSetup s;
  s.count = o.crosses;
  s.box = {0.2, 0.2, 0.05};     // 20 x 20 cm floor
  s.domain_hi = {1.0, 0.2, 1.0};  // room for the flow past x = 0.2 m
  return s;
}

std::filesystem::path pile_cache(const CrossPileOptions& o) {
  char name[128];
  std::snprintf(name, sizeof name, "crosspile_%zu_v%u.bin", o.crosses, kVersion);
  return o.cache / name;
}

// Dense random placement (exact part tests), then settling under gravity until the fastest
// cross is slower than settle_speed.
std::unique_ptr<World> settle_pile(const CrossPileOptions& o) {
  auto w = make_cross_box_world(pile_setup(o));
  const auto t0 = Clock::now();
  const double top = fill_cross_box(*w, pile_setup(o));
  std::fprintf(stderr, "[crosspile] placed %zu crosses up to z = %.3f m in %.1f s\n", w->owned_count(), top,
               std::chrono::duration<double>(Clock::now() - t0).count());
  while (w->time() < o.settle_time_limit) {
    w->run(4000);
    const Diagnostics d = w->diagnostics();
    std::fprintf(stderr, "[crosspile] t = %.3f s  largest speed %.3g m/s  contacts %zu  (%.0f s)\n", w->time(),
                 d.max_speed, d.contacts + d.wall_contacts, std::chrono::duration<double>(Clock::now() - t0).count());
    if (w->time() > 0.1 && d.max_speed < o.settle_speed) break;
  }
  return w;
}

std::unique_ptr<World> load_or_settle(const CrossPileOptions& o, double* seconds) {
  *seconds = 0;
  const std::filesystem::path file = pile_cache(o);
  if (!std::filesystem::exists(file)) {
    const auto t0 = Clock::now();
    auto w = settle_pile(o);
    save_state(*w, file);
    *seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    std::fprintf(stderr, "[crosspile] cached %s\n", file.c_str());
  }
  // Contact memory is not cached: the warm-up of each timing rebuilds it.
  return load_state(make_cross_box_world(pile_setup(o)), file);
}

double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

struct Timing {
  double wall = 1e300;  ///< fastest of the repetitions, us per particle-step
  double cpu = 1e300;   ///< process CPU time of that repetition, us per particle-step
};

// Fastest of o.reps runs of o.steps steps on 1 and on 2 threads, the two taking turns within
// each repetition so that both see the same machine (its speed drifts by tens of per cent over
// a minute). On one thread the CPU time is what the step costs when other jobs keep the thread
// waiting for a core.
std::array<Timing, 2> time_one_and_two_threads(World& w, const CrossPileOptions& o) {
  omp_set_num_threads(1);
  w.run(200);
  std::array<Timing, 2> best;
  for (int r = 0; r < o.reps; ++r) {
    for (int threads = 1; threads <= 2; ++threads) {
      omp_set_num_threads(threads);
      const double cpu0 = process_cpu_seconds();
      const auto start = Clock::now();
      w.run(o.steps);
      const double s = std::chrono::duration<double>(Clock::now() - start).count();
      const double per = 1e6 / static_cast<double>(o.steps * w.owned_count());
      Timing& b = best[threads - 1];
      if (s * per < b.wall) b = {s * per, (process_cpu_seconds() - cpu0) * per};
    }
  }
  return best;
}

double load_average() {
  double l = 0;
  if (std::FILE* f = std::fopen("/proc/loadavg", "r")) {
    if (std::fscanf(f, "%lf", &l) != 1) l = 0;
    std::fclose(f);
  }
  return l;
}

// One thread, counters on: part-pair tests per particle-step and where the time goes.
void profile(World& w, const CrossPileOptions& o, const std::string& prefix,
             void (*metric)(const char*, double, const char*)) {
  omp_set_num_threads(1);
  w.run(50);
  w.timer_mutable().reset();
  reset_composite_stats();
  set_composite_stats_enabled(true);
  const std::uint64_t tsc0 = __rdtsc();
  const auto start = Clock::now();
  w.run(o.steps);
  const double wall = std::chrono::duration<double>(Clock::now() - start).count();
  const double tsc_rate = static_cast<double>(__rdtsc() - tsc0) / wall;  // ticks per second
  set_composite_stats_enabled(false);
  const CompositeStats st = composite_stats_total();
  const double ps = static_cast<double>(o.steps * w.owned_count());
  auto m = [&](const char* name, double v, const char* unit) { metric((prefix + name).c_str(), v, unit); };
  m("_body_pairs_per_particle_step", st.body_pairs / ps, "count");  // bounding spheres overlap
  m("_part_pair_tests_per_particle_step", st.part_pairs / ps, "count");  // past the body-box cull
  m("_narrow_phase_per_particle_step", st.narrow / ps, "count");
  const PhaseTimer& t = w.timer();
  const double narrow = st.narrow_ticks / tsc_rate, force = st.force_ticks / tsc_rate;
  const double composite = st.total_ticks / tsc_rate;
  // Broad phase: list rebuilds, the bounding-sphere loop and the capsule culls with part placing.
  const double broad = t.seconds(Phase::neighbors) + t.seconds(Phase::pair_forces) - narrow - force;
  m("_share_broad_phase", 100 * broad / wall, "%");
  m("_share_narrow_phase", 100 * narrow / wall, "%");
  m("_share_force_model", 100 * force / wall, "%");
  m("_share_walls", 100 * t.seconds(Phase::wall_forces) / wall, "%");
  m("_share_integrate", 100 * t.seconds(Phase::integrate) / wall, "%");
  m("_share_cull_in_pairs", 100 * (composite - narrow - force) / wall, "%");
}

}  // namespace

void run_cross_pile(const CrossPileOptions& o, void (*metric)(const char*, double, const char*)) {
  const int threads = omp_get_max_threads();
  double generating = 0;
  auto w = load_or_settle(o, &generating);
  if (generating > 0) metric("crosspile_settle_seconds", generating, "s");
  const double n = static_cast<double>(w->owned_count());
  metric("crosspile_particles", n, "count");
  omp_set_num_threads(threads);
  w->run(2000);  // rebuild the tangential memory the cache does not hold
  const Diagnostics settled = w->diagnostics();
  metric("crosspile_contacts_per_particle", 2.0 * static_cast<double>(settled.contacts) / n, "count");
  metric("crosspile_wall_contacts_per_particle", static_cast<double>(settled.wall_contacts) / n, "count");
  metric("crosspile_static_max_speed", settled.max_speed, "m/s");
  const auto [s1, s2] = time_one_and_two_threads(*w, o);
  metric("crosspile_static_1t", s1.wall, "us");
  metric("crosspile_static_1t_cpu", s1.cpu, "us");
  metric("crosspile_static_2t", s2.wall, "us");
  metric("crosspile_static_speedup_2t", s1.wall / s2.wall, "x");
  profile(*w, o, "crosspile_static", metric);
  if (o.static_only) return;
  // Flowing: the x+ wall goes, the pile slumps out of the box.
  Wall& side = w->walls_mutable()[1];
  side.motion.kind = WallMotion::Kind::removed;
  side.motion.start_time = w->time();
  omp_set_num_threads(threads);
  w->run(20000);  // 0.05 s: the front is moving
  metric("crosspile_flow_mean_speed", w->diagnostics().mean_speed, "m/s");
  const auto [f1, f2] = time_one_and_two_threads(*w, o);
  metric("crosspile_flow_1t", f1.wall, "us");
  metric("crosspile_flow_1t_cpu", f1.cpu, "us");
  metric("crosspile_flow_2t", f2.wall, "us");
  metric("crosspile_flow_speedup_2t", f1.wall / f2.wall, "x");
  const Diagnostics flowing = w->diagnostics();
  metric("crosspile_flow_contacts_per_particle", 2.0 * static_cast<double>(flowing.contacts) / n, "count");
  profile(*w, o, "crosspile_flow", metric);
  metric("crosspile_loadavg", load_average(), "load");
  omp_set_num_threads(threads);
}

}  // namespace talus::bench
