// The repose angle of a pile (Huet et al. 2021, Appendix B 2, Fig. 23) measured on synthetic
// piles whose flank slopes are known: spheres stacked on a square lattice under two straight
// flanks of different angles.
#include <gtest/gtest.h>

#include <cmath>

#include "talus/analysis/repose_angle.h"

namespace talus {
namespace {

constexpr double kRadius = 0.5e-3;       // m
constexpr double kHeight = 0.04;         // m, pile height: 40 diameters
constexpr double kApex = 0.1;            // m
constexpr double kDegree = M_PI / 180.0;

// Every lattice site whose sphere lies under the pile surface h(x) = H - |x - apex| tan(angle).
Snapshot lattice_pile(double left_deg, double right_deg) {
  Snapshot s;
  const double d = 2 * kRadius;
  for (int i = 0; i * d < 0.2; ++i)
    for (int j = 0; kRadius + j * d < kHeight; ++j) {
      const double x = kRadius + i * d, z = kRadius + j * d;
      const double slope = std::tan((x < kApex ? left_deg : right_deg) * kDegree);
      if (z + kRadius > kHeight - std::abs(x - kApex) * slope) continue;
      ParticleRecord p;
      p.id = static_cast<std::uint32_t>(s.particles.size());
      p.radius = kRadius;
      p.position = {x, 0.002, z};
      s.particles.push_back(p);
    }
  return s;
}

repose::ProfileSettings settings() {
  repose::ProfileSettings p;
  p.bin = 4 * kRadius;
  p.region_lo = {0, 0, 0};
  p.region_hi = {0.2, 0.004, 0.05};
  return p;
}

TEST(ReposeAngle, FlanksOfAKnownPile) {
  const repose::ReposeResult r = repose::measure_repose(lattice_pile(25, 35), settings());
  // The lattice surface is a staircase of step d = H/40; fitted over 60 % of the height
  // (24 steps) its error averages out to a fraction of a degree; 1 deg is a tenth of the
  // spread of Fig. 23 (about 20 to 36 deg).
  EXPECT_NEAR(r.left.angle_deg, 25, 1.0);
  EXPECT_NEAR(r.right.angle_deg, 35, 1.0);
  EXPECT_NEAR(r.angle_deg, 30, 1.0);
  EXPECT_NEAR(r.pile_height, kHeight, 3 * kRadius);  // the top sphere sits one lattice step d (or less) below the apex
  EXPECT_NEAR(r.apex, kApex, settings().bin);
  EXPECT_GE(r.left.bins, 10);
  EXPECT_GE(r.right.bins, 10);
}

TEST(ReposeAngle, SteeperPileGivesLargerAngle) {
  const double gentle = repose::measure_repose(lattice_pile(20, 20), settings()).angle_deg;
  const double steep = repose::measure_repose(lattice_pile(40, 40), settings()).angle_deg;
  EXPECT_NEAR(gentle, 20, 1.0);
  EXPECT_NEAR(steep, 40, 1.0);
}

TEST(ReposeAngle, OnlyParticlesInTheRegionCount) {
  Snapshot s = lattice_pile(30, 30);
  const std::size_t pile = s.particles.size();
  // A column left in the hopper, above the region: it must not become the apex.
  for (int j = 0; j < 20; ++j) {
    ParticleRecord p;
    p.radius = kRadius;
    p.position = {0.03, 0.002, 0.06 + j * 2 * kRadius};
    s.particles.push_back(p);
  }
  const repose::ReposeResult r = repose::measure_repose(s, settings());
  EXPECT_EQ(r.particles, static_cast<int>(pile));
  EXPECT_NEAR(r.apex, kApex, settings().bin);
  EXPECT_NEAR(r.angle_deg, 30, 1.0);
}

TEST(ReposeAngle, TooFewBinsGivesNoAngle) {
  Snapshot s;
  ParticleRecord p;
  p.radius = kRadius;
  p.position = {0.1, 0.002, kRadius};
  s.particles.push_back(p);
  EXPECT_TRUE(std::isnan(repose::measure_repose(s, settings()).angle_deg));
}

}  // namespace
}  // namespace talus
