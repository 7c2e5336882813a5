// The 32,000-sphere chute of talus-bench spread over MPI ranks (one OpenMP thread each unless
// OMP_NUM_THREADS says otherwise):
//   mpirun -n 2 talus-mpi-bench [--cache DIR] [--steps N] [--repetitions R] [--flow-time T]
// Every rank loads the same cached state (talus-bench writes it), the world is spread as
// slabs, warmed up for 200 steps, then timed; the fastest repetition is reported as
// METRIC chute32k_mpi<P>_us_per_particle_step, wall time over (steps x all particles),
// beside the share of the step spent exchanging and the ghosts each rank receives.
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>

#include "../chute_state.h"
#include "talus/parallel/communicator.h"

using namespace talus;

int main(int argc, char** argv) {
  const Communicator& comm = Communicator::world();
  std::string cache = "bench-cache";
  std::uint64_t steps = 2000;
  int repetitions = 3;
  double flow_time = 30;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    const auto value = [&] { return k + 1 < argc ? std::string(argv[++k]) : std::string(); };
    if (a == "--cache") cache = value();
    else if (a == "--steps") steps = std::stoull(value());
    else if (a == "--repetitions") repetitions = std::stoi(value());
    else if (a == "--flow-time") flow_time = std::stod(value());
    else {
      if (comm.rank() == 0) std::fprintf(stderr, "usage: talus-mpi-bench [--cache DIR] [--steps N] [--repetitions R] [--flow-time T]\n");
      return 2;
    }
  }
  const bench::ChuteCase c = bench::make_case("chute32k", 40, 40, 20, flow_time);
  std::unique_ptr<World> world;
  try {
    world = bench::load_state(c, bench::cache_path(cache, c));
  } catch (const std::exception& e) {
    if (comm.rank() == 0)
      std::fprintf(stderr, "talus-mpi-bench: %s (run talus-bench --only chute32k --cache %s first)\n", e.what(), cache.c_str());
    return 1;
  }
  const double particles = static_cast<double>(world->owned_count());
  world->distribute(comm);
  world->run(200);
  double best = 1e300;
  world->timer_mutable().reset();
  for (int r = 0; r < repetitions; ++r) {
    comm.barrier();
    const auto start = std::chrono::steady_clock::now();
    world->run(steps);
    comm.barrier();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  const double exchange = comm.max(world->timer().seconds(Phase::exchange));
  double total = 0;
  for (int k = 0; k < static_cast<int>(Phase::count); ++k) total += world->timer().seconds(static_cast<Phase>(k));
  const double ghosts = comm.max(static_cast<double>(world->halo().count()));
  const double owned_min = -comm.max(-static_cast<double>(world->owned_count()));
  const double owned_max = comm.max(static_cast<double>(world->owned_count()));
  if (comm.rank() == 0) {
    const std::string name = "chute32k_mpi" + std::to_string(comm.size());
    std::printf("METRIC %s_us_per_particle_step %.4f us\n", name.c_str(), 1e6 * best / (steps * particles));
    std::printf("METRIC %s_exchange_share %.3f\n", name.c_str(), total > 0 ? exchange / total : 0.0);
    std::printf("METRIC %s_halo_ghosts_per_rank %.0f\n", name.c_str(), ghosts);
    std::printf("METRIC %s_owned_min_max %.0f %.0f\n", name.c_str(), owned_min, owned_max);
    std::printf("# %d ranks x %d threads, %.0f particles, %llu steps x %d repetitions, fastest %.3f s\n", comm.size(),
                omp_get_max_threads(), particles, static_cast<unsigned long long>(steps), repetitions, best);
  }
  return 0;
}
