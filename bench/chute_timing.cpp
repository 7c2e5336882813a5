#include "chute_timing.h"

#include <omp.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstring>
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

std::vector<TimingResult> time_chute(const ChuteCase& c, const std::filesystem::path& cache_file,
                                     const TimingOptions& o) {
  using Clock = std::chrono::steady_clock;
  const std::size_t counts = o.threads.size();
  std::vector<TimingResult> results(counts);
  std::vector<double> best(counts, std::numeric_limits<double>::infinity()), best_cpu = best;
  std::vector<std::uint64_t> rebuilds(counts, 0);
  auto world = load_state(c, cache_file);
  if (o.contacts) world->contacts() = *o.contacts;
  omp_set_num_threads(o.threads.front());
  world->run(o.warmup);
  for (int rep = 0; rep < o.repetitions; ++rep) {
    for (std::size_t k = 0; k < counts; ++k) {
      omp_set_num_threads(o.threads[k]);
      TimingResult& r = results[k];
      std::array<double, 4> phase_before{};
      for (int f = 0; f < 4; ++f) phase_before[f] = world->timer().seconds(kPhases[f]);
      const std::uint64_t rebuilds_before = world->rebuilds();
      const double cpu0 = process_cpu_seconds();
      const auto t0 = Clock::now();
      world->run(o.steps);
      const double s = std::chrono::duration<double>(Clock::now() - t0).count();
      best_cpu[k] = std::min(best_cpu[k], process_cpu_seconds() - cpu0);
      best[k] = std::min(best[k], s);
      r.seconds += s;
      r.rep_seconds.push_back(s);
      for (int f = 0; f < 4; ++f) r.phase_seconds[f] += world->timer().seconds(kPhases[f]) - phase_before[f];
      rebuilds[k] += world->rebuilds() - rebuilds_before;
    }
  }

  const ParticleStore& p = world->particles();
  const Diagnostics d = world->diagnostics();
  std::size_t fixed = 0;
  for (std::size_t i = 0; i < world->owned_count(); ++i) fixed += p.is_fixed(i);
  for (std::size_t k = 0; k < counts; ++k) {
    TimingResult& r = results[k];
    r.particles = world->owned_count();
    r.fixed = fixed;
    r.steps = o.steps * static_cast<std::uint64_t>(o.repetitions);
    r.rebuilds = rebuilds[k];
    const double per = 1e6 / (static_cast<double>(o.steps) * static_cast<double>(r.particles));
    r.us_per_particle_step = best[k] * per;
    r.us_mean = r.seconds / o.repetitions * per;
    r.us_cpu = best_cpu[k] * per;
    r.contacts = d.contacts;
    r.mean_speed = d.mean_speed;
    r.pair_entries = world->pair_entries();
    r.engine_bytes = world->memory_bytes();
  }
  return results;
}

bool same_on_one_and_two_threads(const ChuteCase& c, const std::filesystem::path& cache_file, std::uint64_t steps) {
  std::vector<Vec3> position_by_gid[2];
  for (int threads = 1; threads <= 2; ++threads) {
    omp_set_num_threads(threads);
    auto world = load_state(c, cache_file);
    world->run(steps);
    const ParticleStore& p = world->particles();
    std::vector<Vec3>& x = position_by_gid[threads - 1];
    x.resize(world->owned_count());
    for (std::size_t i = 0; i < x.size(); ++i) x[p.gid[i]] = p.position[i];
  }
  return position_by_gid[0].size() == position_by_gid[1].size() &&
         std::memcmp(position_by_gid[0].data(), position_by_gid[1].data(), position_by_gid[0].size() * sizeof(Vec3)) == 0;
}

}  // namespace talus::bench
