#pragma once
// The cross-pile benchmark: crosses of Huet et al. 2021 (Sec. III B, Table I) poured into a box
// and settled, timed while static and while flowing after a side wall is removed.
#include <cstddef>
#include <cstdint>

namespace talus::bench {

struct CrossPileOptions {
  std::size_t crosses = 2000;
  std::uint64_t steps = 1000;  ///< timed steps per thread count and state
  double settle_speed = 5e-3;  ///< m/s: the pile counts as settled below this largest speed
  double settle_time_limit = 3;  ///< s
};

// Builds and settles the pile (minutes for 2000 crosses), then prints the crosspile_* METRIC lines.
void run_cross_pile(const CrossPileOptions& o, void (*metric)(const char* name, double value, const char* unit));

}  // namespace talus::bench
