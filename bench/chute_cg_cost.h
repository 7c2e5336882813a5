#pragma once
// Cost of coarse graining one snapshot of a cached chute state (Weinhart et al. 2012, Sect. 3)
// relative to one time step, on one thread: a 1D depth profile of 200 points and a 3D grid of
// 40 x 20 x 40, Gaussian of width 0.25 d (Sect. 7).
#include <filesystem>
#include <functional>

#include "chute_state.h"

namespace talus::bench {

struct CgCost {
  double step_seconds = 0;      ///< one time step (fastest of the repetitions)
  double snapshot_seconds = 0;  ///< World::snapshot()
  double cg_1d_seconds = 0;     ///< coarse_grain on CgGrid::depth(200 points)
  double cg_3d_seconds = 0;     ///< coarse_grain on CgGrid::volume(40, 20, 40)
};

CgCost time_chute_coarse_graining(const ChuteCase& c, const std::filesystem::path& cache_file, int repetitions);

}  // namespace talus::bench
