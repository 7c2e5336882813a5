#pragma once
// The cross-pile benchmark: crosses of Huet et al. 2021 (Sec. III B, Table I) placed densely
// at random (exact part overlap tests), settled in a 20 x 20 cm box and cached; then timed
// while static and while flowing after a side wall is removed.
#include <cstddef>
#include <cstdint>
#include <filesystem>

#include "talus/world/world.h"

namespace talus::bench {

struct CrossPileOptions {
  std::size_t crosses = 2000;
  std::uint64_t steps = 1000;      ///< timed steps per thread count and state
  int reps = 8;                    ///< repetitions of each timing (the fastest is kept)
  bool static_only = false;        ///< skip the flowing state (quick comparisons)
  bool narrow_phase_reuse = true;  ///< WorldSettings::narrow_phase_reuse (off: the A/B reference)
  double manifold_refit = 0;       ///< WorldSettings::manifold_refit (0: clip every step)
  double manifold_recycle = kDefaultManifoldRecycle;  ///< WorldSettings::manifold_recycle (0: no recycled points)
  double settle_speed = 3e-2;      ///< m/s: settled below this largest speed (surface crosses creep at 1-3 cm/s)
  double settle_time_limit = 1.5;  ///< s of simulated time
  std::filesystem::path cache;     ///< directory of the cached settled pile
};

// Loads the settled pile from the cache (or builds, settles and caches it: minutes), then prints
// the crosspile_* METRIC lines.
void run_cross_pile(const CrossPileOptions& o, void (*metric)(const char* name, double value, const char* unit));

}  // namespace talus::bench
