// Speed of the binned coarse graining on a dense 4000-particle snapshot with ~6 contacts per
// particle: a 1D profile of 200 points and a 3D grid of 40 x 20 x 40. Times are printed; the
// bounds are loose (shared CI machines), the spot checks against brute force are tight.
#include <chrono>
#include <iostream>
#include <random>

#include <gtest/gtest.h>

#include "talus/analysis/coarse_grain.h"
#include "test_coarse_grain_scenes.h"

namespace talus {
namespace {

template <class Fn>
double seconds(Fn&& fn) {
  const auto t0 = std::chrono::steady_clock::now();
  fn();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void spot_check(const Snapshot& s, const CgFields& fields, const CgFunction& f) {
  std::mt19937 rng(5);
  for (int n = 0; n < 20; ++n) {
    const int k = std::uniform_int_distribution<int>(0, fields.grid.size() - 1)(rng);
    const CgValues ref = coarse_grain_at(s, fields.grid, f, fields.grid.point(k));
    EXPECT_NEAR(fields.values[k].density, ref.density, 1e-12 * (1 + ref.density));
    EXPECT_LT((fields.values[k].stress() - ref.stress()).norm(), 1e-12 * (1 + ref.stress().norm()));
  }
}

TEST(CoarseGrainTiming, FourThousandParticles) {
  const Snapshot s = cg_test::jittered_packing(20, 10, 20, 1.0, 42);
  ASSERT_EQ(s.particles.size(), 4000u);
  std::cout << "  " << s.particles.size() << " particles, " << s.contacts.size() << " contacts\n";
  const CgFunction f1 = CgFunction::gaussian(0.5, 1), f3 = CgFunction::gaussian(0.5, 3);
  CgFields prof, vol;
  coarse_grain(s, CgGrid::depth(0, 1, 2), f1);  // start the thread pool outside the timing
  const double t1 = seconds([&] { prof = coarse_grain(s, CgGrid::depth(-0.5, 20.5, 200), f1); });
  const double t3 = seconds([&] { vol = coarse_grain(s, CgGrid::volume({0, 0, 0}, {19.5, 9.5, 19.5}, 40, 20, 40), f3); });
  std::cout << "  1D 200 points: " << t1 * 1e3 << " ms; 3D 40x20x40 (w = 0.5 d): " << t3 * 1e3 << " ms\n";
  EXPECT_LT(t1, 2.0);
  EXPECT_LT(t3, 20.0);
  spot_check(s, prof, f1);
  spot_check(s, vol, f3);
}

}  // namespace
}  // namespace talus
