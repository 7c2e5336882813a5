// 1000 crosses of Huet et al. 2021 (Sec. III B, Table I: k_n = 4.5e5 N/m, e_n = 0.85,
// k_t = 300 N/m, gamma_t = 1e3 1/s, mu = 0.46 / 0.62 at the walls, dt = 2.5e-6 s) poured into a
// box come to rest, and the largest overlap of the resting pile stays below 1 % of the radius
// of the equal-volume sphere, the delta_max Table I's k_n was chosen for (Sec. III C).
// The crosses are placed densely at random with exact part tests (body_insertion.h),
// so they fall a few centimetres instead of the half metre that bounding-sphere placement needs.
#include <gtest/gtest.h>

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "talus/scenario/cross_box.h"

namespace talus {
namespace {

double largest_overlap(const World& w) {
  double m = 0;
  for (const SubContactStore* store : {&w.pair_sub_contacts(), &w.wall_sub_contacts()})
    for (std::size_t e = 0; e < store->entries(); ++e)
      for (const SubContact& s : store->of(e)) m = std::max(m, s.overlap);
  return m;
}

// About 1.4e8 cross-steps (0.34 s of 1000 crosses at dt = 2.5e-6 s): 200 s on two idle cores.
TEST(CrossPour, ThousandCrossesSettleToAStaticPileWithSmallOverlaps) {
  CrossBoxSetup setup;
  setup.count = 1000;
  setup.box = {0.15, 0.15, 0.04};
  setup.domain_hi = {0.15, 0.15, 0.5};
  auto w = make_cross_box_world(setup);
  const auto start = std::chrono::steady_clock::now();
  const double top = fill_cross_box(*w, setup);
  ASSERT_EQ(w->owned_count(), setup.count);
  const double r_eq = huet_cross_equivalent_radius();
  EXPECT_NEAR(r_eq, 4.21e-3, 0.01e-3);  // (3 V / 4 pi)^(1/3), V = 0.312 cm^3 (Sec. III B)

  // Static: the fastest cross slower than 3 cm/s, i.e. moving less than 7.5e-8 m per time
  // step, 2e-5 of the 4.2 mm radius: a few crosses on the surface still creep when the pile
  // has stopped (a 600-cross pile measured: largest speed 0.014-0.028 m/s from t = 0.37 s on).
  constexpr double kStaticSpeed = 3e-2;
  double peak_overlap = 0;
  Diagnostics d;
  while (w->time() < 0.6) {
    w->run(4000);  // 0.01 s
    d = w->diagnostics();
    peak_overlap = std::max(peak_overlap, largest_overlap(*w));
    if (w->time() > 0.1 && d.max_speed < kStaticSpeed) break;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double resting = largest_overlap(*w);
  std::printf("1000 crosses placed up to z = %.3f m, static at t = %.3f s (%.0f s wall, %d threads); largest overlap "
              "resting %.3g m = %.3g %% of r_eq, during the fall %.3g m = %.3g %%; speed %.3g m/s; %zu contact points\n",
              top, w->time(), seconds, omp_get_max_threads(), resting, 100 * resting / r_eq, peak_overlap,
              100 * peak_overlap / r_eq, d.max_speed, d.contacts + d.wall_contacts);
  EXPECT_LT(d.max_speed, kStaticSpeed);
  EXPECT_LT(resting, 0.01 * r_eq);
  EXPECT_LT(peak_overlap, 0.01 * r_eq);  // holds during the fall too: k_n is for impacts of 2.4 m/s
  // Every cross is still in the box.
  const ParticleStore& p = w->particles();
  for (std::size_t i = 0; i < p.owned; ++i) {
    ASSERT_GE(p.position[i].z, 0);
    ASSERT_GE(p.position[i].x, 0);
    ASSERT_LE(p.position[i].x, setup.box.x);
    ASSERT_GE(p.position[i].y, 0);
    ASSERT_LE(p.position[i].y, setup.box.y);
  }
}

}  // namespace
}  // namespace talus
