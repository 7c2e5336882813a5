#include "chute_cg_cost.h"

#include <omp.h>

#include <algorithm>
#include <chrono>

#include "talus/analysis/coarse_grain.h"

namespace talus::bench {
namespace {

template <class Fn>
double fastest(int repetitions, Fn&& fn) {
  double best = 1e300;
  for (int r = 0; r < repetitions; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    fn();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}

}  // namespace

CgCost time_chute_coarse_graining(const ChuteCase& c, const std::filesystem::path& cache_file, int repetitions) {
  omp_set_num_threads(1);
  auto world = load_state(c, cache_file);
  world->run(200);  // rebuild the contact memory: snapshot forces as in a running chute
  CgCost r;
  constexpr int kSteps = 200;
  r.step_seconds = fastest(repetitions, [&] { world->run(kSteps); }) / kSteps;
  Snapshot snap;
  r.snapshot_seconds = fastest(repetitions, [&] { snap = world->snapshot(); });
  const double h = c.setup.fill_height;
  const CgFunction f1 = CgFunction::gaussian(0.25, 1), f3 = CgFunction::gaussian(0.25, 3);
  const CgGrid depth = CgGrid::depth(-1, 1.2 * h + 5, 200);
  const CgGrid volume = CgGrid::volume({0.25, 0.125, -1}, {c.setup.length - 0.25, c.setup.width - 0.125, 1.2 * h + 5}, 40, 20, 40);
  r.cg_1d_seconds = fastest(repetitions, [&] { (void)coarse_grain(snap, depth, f1); });
  r.cg_3d_seconds = fastest(repetitions, [&] { (void)coarse_grain(snap, volume, f3); });
  return r;
}

}  // namespace talus::bench
