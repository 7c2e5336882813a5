#include "chute_timing.h"

#include <omp.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <limits>

namespace talus::bench {

namespace {
// CPU time of the whole process, s: on a shared machine the 1-thread figure without the
// time this process waited for a core.
double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

constexpr Phase kPhases[4] = {Phase::integrate, Phase::neighbors, Phase::pair_forces, Phase::wall_forces};
}

TimingResult time_chute(const ChuteCase& c, const std::filesystem::path& cache_file, const TimingOptions& o) {
  using Clock = std::chrono::steady_clock;
  omp_set_num_threads(o.threads);
  auto world = load_state(c, cache_file);
  world->run(o.warmup);

  TimingResult r;
  const ParticleStore& p = world->particles();
  r.particles = world->owned_count();
  for (std::size_t i = 0; i < r.particles; ++i) r.fixed += p.is_fixed(i);

  std::array<double, 4> phase_before{};
  for (int k = 0; k < 4; ++k) phase_before[k] = world->timer().seconds(kPhases[k]);
  const std::uint64_t rebuilds_before = world->rebuilds();
  double best = std::numeric_limits<double>::infinity(), best_cpu = best;
  for (int rep = 0; rep < o.repetitions; ++rep) {
    const double cpu0 = process_cpu_seconds();
    const auto t0 = Clock::now();
    world->run(o.steps);
    const double s = std::chrono::duration<double>(Clock::now() - t0).count();
    best_cpu = std::min(best_cpu, process_cpu_seconds() - cpu0);
    best = std::min(best, s);
    r.seconds += s;
  }
  r.steps = o.steps * static_cast<std::uint64_t>(o.repetitions);
  for (int k = 0; k < 4; ++k) r.phase_seconds[k] = world->timer().seconds(kPhases[k]) - phase_before[k];
  r.rebuilds = world->rebuilds() - rebuilds_before;
  const double per = 1e6 / (static_cast<double>(o.steps) * static_cast<double>(r.particles));
  r.us_per_particle_step = best * per;
  r.us_mean = r.seconds / o.repetitions * per;
  r.us_cpu = best_cpu * per;

  const Diagnostics d = world->diagnostics();
  r.contacts = d.contacts;
  r.mean_speed = d.mean_speed;
  r.pair_entries = world->pair_entries();
  r.engine_bytes = world->memory_bytes();
  r.position_by_gid.resize(r.particles);
  for (std::size_t i = 0; i < r.particles; ++i) r.position_by_gid[p.gid[i]] = p.position[i];
  return r;
}

}  // namespace talus::bench
