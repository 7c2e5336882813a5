#include "guard_cost.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "talus/world/state_guard.h"

namespace talus::bench {

GuardCost time_state_guard(const ChuteCase& c, const std::filesystem::path& cache_file, int threads, int repetitions) {
  omp_set_num_threads(threads);
  auto world = load_state(c, cache_file);
  world->run(200);  // rebuild the contact memory, as in a running chute
  using Clock = std::chrono::steady_clock;
  constexpr std::uint64_t kBatch = 64;
  GuardCost r{1e300, 1e300};
  unsigned faults = 0;
  for (int k = 0; k < repetitions; ++k) {
    const auto t0 = Clock::now();
    world->run(kBatch);
    const auto t1 = Clock::now();
    faults |= scan_state(world->particles(), world->settings().domain, world->settings().time_step);
    const auto t2 = Clock::now();
    r.step_seconds = std::min(r.step_seconds, std::chrono::duration<double>(t1 - t0).count() / kBatch);
    r.scan_seconds = std::min(r.scan_seconds, std::chrono::duration<double>(t2 - t1).count());
  }
  if (faults != 0) throw std::runtime_error(c.name + ": the blow-up guard flags the flowing chute");
  return r;
}

}  // namespace talus::bench
