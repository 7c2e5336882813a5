#pragma once
// The shape-pile benchmark: piles of 1000 icosahedra, hexapods and tetrapods
// (shape_pile_cases.h), each placed densely at random (exact part tests) and settled for a fixed
// simulated time, then timed static, and flowing after the x+ wall is removed, on 1 and 2
// threads, as the cross pile (cross_pile.h). Both states are cached (shape_pile_states.h), so
// that only the first run pays for settling and for the flow's start.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include "pile_timing.h"

namespace talus::bench {

struct ShapePileOptions {
  std::size_t count = 1000;     ///< bodies per pile
  std::uint64_t steps = 500;    ///< timed steps per thread count and state
  int reps = 3;                 ///< repetitions of each timing (the fastest is kept)
  bool static_only = false;     ///< skip the flowing states
  std::string shape;            ///< one case's name; empty: all three
  // Fraction of each case's settling and flow times (1: the benchmark; --quick's 0.1 leaves the
  // piles unsettled, a smoke run of the code path).
  double time_scale = 1;
  int gen_threads = 0;          ///< threads that generate missing states; 0: omp_get_max_threads()
  std::filesystem::path cache;  ///< directory of the cached states
};

// Loads each pile's states from the cache (or generates them: minutes, tens for the tetrapods),
// then prints the shapes_<case>_* METRIC lines and a summary of microseconds per particle-step.
void run_shape_piles(const ShapePileOptions& o, MetricSink metric);

}  // namespace talus::bench
