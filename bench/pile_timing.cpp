#include "pile_timing.h"

#include <omp.h>
#include <x86intrin.h>

#include <chrono>
#include <ctime>

#include "talus/world/composite_stats.h"

namespace talus::bench {

namespace {

using Clock = std::chrono::steady_clock;

double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace

std::array<PileTiming, 2> time_one_and_two_threads(World& w, std::uint64_t steps, int reps) {
  omp_set_num_threads(1);
  w.run(200);
  std::array<PileTiming, 2> best;
  for (int r = 0; r < reps; ++r) {
    for (int threads = 1; threads <= 2; ++threads) {
      omp_set_num_threads(threads);
      const double cpu0 = process_cpu_seconds();
      const auto start = Clock::now();
      w.run(steps);
      const double s = std::chrono::duration<double>(Clock::now() - start).count();
      const double per = 1e6 / static_cast<double>(steps * w.owned_count());
      PileTiming& b = best[threads - 1];
      if (s * per < b.wall) b = {s * per, (process_cpu_seconds() - cpu0) * per};
    }
  }
  return best;
}

void profile_pile(World& w, std::uint64_t steps, const std::string& prefix, MetricSink metric) {
  omp_set_num_threads(1);
  w.run(50);
  w.timer_mutable().reset();
  reset_composite_stats();
  set_composite_stats_enabled(true);
  const std::uint64_t tsc0 = __rdtsc();
  const auto start = Clock::now();
  w.run(steps);
  const double wall = std::chrono::duration<double>(Clock::now() - start).count();
  const double tsc_rate = static_cast<double>(__rdtsc() - tsc0) / wall;  // ticks per second
  set_composite_stats_enabled(false);
  const CompositeStats st = composite_stats_total();
  const double ps = static_cast<double>(steps * w.owned_count());
  auto m = [&](const char* name, double v, const char* unit) { metric((prefix + name).c_str(), v, unit); };
  m("_body_pairs_per_particle_step", st.body_pairs / ps, "count");  // bounding spheres overlap
  m("_part_pair_tests_per_particle_step", st.part_pairs / ps, "count");  // past the body-box cull
  m("_narrow_phase_per_particle_step", st.narrow / ps, "count");
  // Touching box part pairs served from their stored feature (box_pair_reuse.h), of all box
  // part pairs that reached the narrow phase.
  const double box_queries = static_cast<double>(st.box_full_queries + st.box_reused);
  m("_reuse_share", box_queries > 0 ? st.box_reused / box_queries : 0.0, "fraction");
  m("_refit_share", box_queries > 0 ? st.box_refit / box_queries : 0.0, "fraction");
  m("_recycle_share", box_queries > 0 ? st.box_recycled / box_queries : 0.0, "fraction");
  m("_full_box_queries_per_particle_step", st.box_full_queries / ps, "count");
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

}  // namespace talus::bench
