#pragma once
// Times a cached chute state on a given number of OpenMP threads.
#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "chute_state.h"

namespace talus::bench {

struct TimingOptions {
  std::vector<int> threads{1, 2};  ///< thread counts, timed in turn within each repetition
  std::uint64_t warmup = 200;      ///< steps after loading, untimed: rebuilds the contact memory
  std::uint64_t steps = 2000;      ///< steps per timed repetition and thread count
  int repetitions = 3;             ///< the fastest repetition is reported (other jobs share the machine)
  const ContactTable* contacts = nullptr;  ///< replaces the cached world's contact law after loading (null: keep)
};

struct TimingResult {
  std::size_t particles = 0;       ///< owned particles, flowing + fixed base
  std::size_t fixed = 0;           ///< base particles
  double us_per_particle_step = 0; ///< microseconds, fastest repetition / (steps * particles)
  double us_mean = 0;              ///< same, mean over the repetitions
  double us_cpu = 0;               ///< same with process CPU time (all threads) instead of wall time, fastest repetition
  std::array<double, 4> phase_seconds{};  ///< integrate, neighbors, pair_forces, wall_forces, all repetitions
  double seconds = 0;              ///< wall time of all repetitions
  std::vector<double> rep_seconds; ///< wall time of each repetition, in order
  std::uint64_t steps = 0;         ///< timed steps, all repetitions
  std::uint64_t rebuilds = 0;      ///< neighbour-list rebuilds during the timed steps
  std::size_t contacts = 0;        ///< particle-particle contacts at the end
  std::size_t pair_entries = 0;    ///< half-list entries at the end
  std::size_t engine_bytes = 0;    ///< World::memory_bytes() at the end
  double mean_speed = 0;           ///< of the flowing particles at the end, sqrt(g d)
};

// One result per thread count of `o`. The counts take turns on one world, repetition by
// repetition: this machine's speed drifts by tens of per cent over a minute, and timing the
// counts in separate blocks would fold that drift into their ratio. (Results do not depend on
// the thread count, so the world flows on as if one count ran all the steps.)
std::vector<TimingResult> time_chute(const ChuteCase& c, const std::filesystem::path& cache_file,
                                     const TimingOptions& o);

// Whether `steps` steps from the cached state end with the same positions, to the bit, on 1
// and on 2 threads.
bool same_on_one_and_two_threads(const ChuteCase& c, const std::filesystem::path& cache_file, std::uint64_t steps);

}  // namespace talus::bench
