// Time averaging of coarse-grained fields (Weinhart et al. 2012, Eq. 43).
#include <gtest/gtest.h>

#include "talus/analysis/cg_time_average.h"
#include "talus/analysis/coarse_grain.h"
#include "test_coarse_grain_scenes.h"

namespace talus {
namespace {

// One particle moving at 1 then 3 m/s along x: each snapshot has no kinetic stress (a lone
// particle moves with its own field), the mean velocity is 2, and the mean momentum flux keeps
// the temporal fluctuation m (v - <v>)^2 W that balance checks need.
TEST(CoarseGrainAverage, MeanFieldsOfTwoSnapshots) {
  Snapshot s;
  s.domain_min = {0, 0, -2};
  s.domain_max = {1, 1, 2};
  s.particles = {cg_test::particle({0.5, 0.5, 0}, 2)};
  const CgFunction f = CgFunction::gaussian(0.3, 1);
  const CgGrid grid = CgGrid::depth(-1, 1, 21);
  CgTimeAverage avg;
  for (double vx : {1.0, 3.0}) {
    s.particles[0].velocity = {vx, 0, 0};
    avg.add(coarse_grain(s, grid, f));
  }
  EXPECT_EQ(avg.count(), 2);
  const CgFields m = avg.mean();
  for (int k = 0; k < grid.size(); ++k) {
    const double z = grid.point(k).z, w = 2 * f.value(z * z);
    const CgValues& v = m.values[k];
    EXPECT_NEAR(v.density, w, 1e-14);
    if (w > 0) EXPECT_NEAR(v.velocity().x, 2, 1e-14);
    EXPECT_NEAR(v.kinetic_stress(0, 0), 0, 1e-14);
    EXPECT_NEAR(v.momentum_flux(0, 0), 5 * w, 1e-13);
    EXPECT_NEAR(v.momentum_flux(0, 0) - v.momentum.x * v.momentum.x / (v.density > 0 ? v.density : 1), w, 1e-13);
  }
  CgTimeAverage other;
  other.add(coarse_grain(s, CgGrid::depth(-1, 1, 11), f));
  EXPECT_THROW(other.add(coarse_grain(s, grid, f)), std::invalid_argument);
}

}  // namespace
}  // namespace talus
