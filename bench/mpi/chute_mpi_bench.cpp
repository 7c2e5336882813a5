// The 32,000-sphere chute of talus-bench spread over MPI ranks (one OpenMP thread each unless
// OMP_NUM_THREADS says otherwise):
//   mpirun -n 2 talus-mpi-bench [--cache DIR] [--steps N] [--repetitions R] [--flow-time T]
//                               [--tiles NX NY]
// Every rank loads the same cached state (talus-bench writes it), the world is spread as
// slabs, warmed up for 200 steps, then timed; the fastest repetition is reported as
// METRIC chute32k_mpi<P>_us_per_particle_step, wall time over (steps x all particles),
// beside the share of the step spent exchanging and the ghosts each rank receives.
// --tiles repeats the state NX x NY times over a larger periodic base (6 x 5 tiles: 1.05 x 10^6
// spheres, named chute1055k) and adds its memory: the engine's bytes per particle
// (World::memory_bytes summed over ranks) and each rank's peak resident memory, which includes
// the whole state every rank reads before it keeps its slab.
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "../chute_state.h"
#include "../proc_memory.h"
#include "talus/parallel/communicator.h"

using namespace talus;

int main(int argc, char** argv) {
  const Communicator& comm = Communicator::world();
  std::string cache = "bench-cache";
  std::uint64_t steps = 2000;
  int repetitions = 3;
  double flow_time = 30;
  int tiles_x = 1, tiles_y = 1;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    const auto value = [&] { return k + 1 < argc ? std::string(argv[++k]) : std::string(); };
    if (a == "--cache") cache = value();
    else if (a == "--steps") steps = std::stoull(value());
    else if (a == "--repetitions") repetitions = std::stoi(value());
    else if (a == "--flow-time") flow_time = std::stod(value());
    else if (a == "--tiles" && k + 2 < argc) {
      tiles_x = std::stoi(argv[++k]);
      tiles_y = std::stoi(argv[++k]);
    }
    else {
      if (comm.rank() == 0) std::fprintf(stderr, "usage: talus-mpi-bench [--cache DIR] [--steps N] [--repetitions R] [--flow-time T] [--tiles NX NY]\n");
      return 2;
    }
  }
  const bench::ChuteCase c = bench::make_case("chute32k", 40, 40, 20, flow_time);
  std::unique_ptr<World> world;
  try {
    const std::filesystem::path file = bench::cache_path(cache, c);
    world = tiles_x * tiles_y > 1 ? bench::load_state_tiled(c, file, tiles_x, tiles_y) : bench::load_state(c, file);
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
  const std::uint64_t rebuilds_before = world->rebuilds();
  for (int r = 0; r < repetitions; ++r) {
    comm.barrier();
    const auto start = std::chrono::steady_clock::now();
    world->run(steps);
    comm.barrier();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  // The share of time in messages: the halo, migration and the rebuild vote, waits included.
  const double exchange = comm.max(world->timer().seconds(Phase::exchange) + world->timer().seconds(Phase::rebuild_vote) +
                                   world->timer().seconds(Phase::migration));
  double total = 0;
  for (int k = 0; k < static_cast<int>(Phase::count); ++k) total += world->timer().seconds(static_cast<Phase>(k));
  const double ghosts = comm.max(static_cast<double>(world->halo().count()));
  const double owned_min = -comm.max(-static_cast<double>(world->owned_count()));
  const double owned_max = comm.max(static_cast<double>(world->owned_count()));
  // Each rank's seconds per phase: where the exchange's waiting comes from.
  const int phases = static_cast<int>(Phase::count);
  std::vector<double> phase_seconds(static_cast<std::size_t>(comm.size() * phases), 0.0);
  for (int k = 0; k < phases; ++k)
    phase_seconds[static_cast<std::size_t>(comm.rank() * phases + k)] = world->timer().seconds(static_cast<Phase>(k));
  comm.sum_in_place(phase_seconds);
  const double engine_bytes = comm.sum(static_cast<double>(world->memory_bytes()));
  const double peak_rss_mib = comm.max(static_cast<double>(bench::peak_resident_kib()) / 1024);
  if (comm.rank() == 0) {
    const bool tiled = tiles_x * tiles_y > 1;
    const std::string name = (tiled ? "chute" + std::to_string(std::lround(particles / 1000)) + "k" : "chute32k") +
                             "_mpi" + std::to_string(comm.size());
    std::printf("METRIC %s_us_per_particle_step %.4f us\n", name.c_str(), 1e6 * best / (steps * particles));
    std::printf("METRIC %s_exchange_share %.3f\n", name.c_str(), total > 0 ? exchange / total : 0.0);
    std::printf("METRIC %s_steps_per_rebuild %.1f\n", name.c_str(),
                static_cast<double>(steps) * repetitions / std::max<double>(1.0, static_cast<double>(world->rebuilds() - rebuilds_before)));
    std::printf("METRIC %s_halo_ghosts_per_rank %.0f\n", name.c_str(), ghosts);
    std::printf("METRIC %s_owned_min_max %.0f %.0f\n", name.c_str(), owned_min, owned_max);
    if (tiled) {
      std::printf("METRIC %s_engine_bytes_per_particle %.0f B\n", name.c_str(), engine_bytes / particles);
      std::printf("METRIC %s_peak_rss_per_rank %.0f MiB\n", name.c_str(), peak_rss_mib);
    }
    for (int r = 0; r < comm.size(); ++r) {
      std::printf("# rank %d seconds:", r);
      for (int k = 0; k < phases; ++k)
        std::printf(" %s %.3f", phase_name(static_cast<Phase>(k)), phase_seconds[static_cast<std::size_t>(r * phases + k)]);
      std::printf("\n");
    }
    std::printf("# %d ranks x %d threads, %.0f particles, %llu steps x %d repetitions, fastest %.3f s\n", comm.size(),
                omp_get_max_threads(), particles, static_cast<unsigned long long>(steps), repetitions, best);
  }
  return 0;
}
