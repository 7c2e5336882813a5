// Centre-of-mass shift, mean speeds and the regime of synthetic collapses with known answers.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "talus/analysis/collapse_centre_of_mass.h"
#include "talus/analysis/collapse_regime.h"
#include "talus/analysis/collapse_speed.h"
#include "talus/analysis/collapse_summary.h"

namespace talus::collapse {
namespace {

// N particles of random mass uniformly in [0, L0] x [0, W] x [0, H0].
Snapshot random_column(int n, double L0, double W, double H0, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Snapshot s;
  s.gravity = {0, 0, -9.81};
  for (int k = 0; k < n; ++k) {
    ParticleRecord p;
    p.id = static_cast<std::uint32_t>(k);
    p.mass = 0.5 + u(rng);
    p.radius = 0.005;
    p.position = {L0 * u(rng), W * u(rng), H0 * u(rng)};
    s.particles.push_back(p);
  }
  return s;
}

TEST(CollapseCentreOfMass, RandomPileSpreadTwiceAsLongDoublesX) {
  const Snapshot before = random_column(500, 0.1, 0.05, 0.3, 7);
  Snapshot after = before;
  // Stretch x by 2 and squash z by 2: an affine map moves the centre of mass the same way,
  // whatever the random positions and masses.
  for (ParticleRecord& p : after.particles) p.position = {2 * p.position.x, p.position.y, 0.5 * p.position.z};
  const CentreOfMassShift s = centre_of_mass_shift(before, after);
  EXPECT_NEAR(s.dx_over_x0, 1.0, 1e-12);
  EXPECT_NEAR(s.displacement.x, s.initial.x, 1e-12);
  EXPECT_NEAR(s.displacement.z, -0.5 * s.initial.z, 1e-12);
  EXPECT_NEAR(s.initial.x, 0.05, 0.005);  // about L0 / 2, as Appendix C assumes
}

TEST(CollapseCentreOfMass, FixedParticlesAndUniformShift) {
  Snapshot before = random_column(100, 0.1, 0.05, 0.3, 3);
  ParticleRecord base;
  base.fixed = true;
  base.mass = 1e6;
  base.position = {5, 5, 5};
  before.particles.push_back(base);
  Snapshot after = before;
  const Vec3 shift{0.02, -0.001, -0.03};
  for (ParticleRecord& p : after.particles)
    if (!p.fixed) p.position += shift;
  const CentreOfMassShift s = centre_of_mass_shift(before, after);
  EXPECT_NEAR(s.displacement.x, shift.x, 1e-12);
  EXPECT_NEAR(s.displacement.y, shift.y, 1e-12);
  EXPECT_NEAR(s.displacement.z, shift.z, 1e-12);
  EXPECT_LT(s.initial.x, 0.1);  // the heavy fixed particle is not part of the pile
}

TEST(CollapseSpeed, MeansAndFreeFallScaling) {
  Snapshot s;
  s.gravity = {0, 0, -9.81};
  s.time = 0.35;
  ParticleRecord a, b, fixed;
  a.velocity = {3, 4, 0};
  a.angular_velocity = {0, 2, 0};
  b.velocity = {0, 0, -1};
  b.angular_velocity = {0, 0, 0};
  fixed.fixed = true;
  fixed.velocity = {100, 0, 0};
  s.particles = {a, b, fixed};
  const MeanSpeeds m = mean_speeds(s);
  EXPECT_DOUBLE_EQ(m.translational, 3.0);
  EXPECT_DOUBLE_EQ(m.angular, 1.0);
  const double H0 = 0.2, tau = std::sqrt(H0 / 9.81);
  EXPECT_DOUBLE_EQ(collapse_time_scale(H0, 9.81), tau);
  const ScaledSpeeds sc = scaled_speeds(s, H0, 0.05);
  EXPECT_NEAR(sc.time, 0.30 / tau, 1e-12);
  EXPECT_NEAR(sc.translational, 3.0 / std::sqrt(9.81 * H0), 1e-12);
  EXPECT_NEAR(sc.angular, tau, 1e-12);
}

TEST(CollapseRegime, StableFracturedCollapsed) {
  const double L0 = 0.1, H0 = 0.3, d = 0.01;
  const Snapshot before = random_column(400, L0, 0.05, H0, 11);

  // Nothing moved, runout and height within a particle: stable.
  RegimeReport r = classify_regime(before, before, {L0, H0, L0 + 0.5 * d, H0 - 0.5 * d, d});
  EXPECT_EQ(r.regime, Regime::Stable);
  EXPECT_EQ(r.displaced, 0);

  // The front half flowed forward by three particles; the back kept its height: fractured.
  Snapshot fractured = before;
  for (ParticleRecord& p : fractured.particles)
    if (p.position.x > L0 / 2) p.position += Vec3{3 * d, 0, -3 * d};
  r = classify_regime(before, fractured, {L0, H0, L0 + 3 * d, H0, d});
  EXPECT_EQ(r.regime, Regime::Fractured);
  EXPECT_NEAR(r.displaced_fraction, 0.5, 0.1);
  EXPECT_NEAR(r.runout_excess, 3.0, 1e-12);

  // The height dropped by far more than a particle: collapsed.
  r = classify_regime(before, fractured, {L0, H0, 2 * L0, 0.5 * H0, d});
  EXPECT_EQ(r.regime, Regime::Collapsed);
  EXPECT_STREQ(to_string(r.regime), "collapsed");
}

TEST(CollapseSummary, UndisturbedBlockIsStableWithZeroRatios) {
  const double side = 0.01;
  Snapshot s;
  s.gravity = {0, 0, -9.81};
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 15; ++k) {
        ParticleRecord p;
        p.id = static_cast<std::uint32_t>(s.particles.size());
        p.mass = 1;
        p.radius = side;
        p.position = {(i + 0.5) * side, (j + 0.5) * side, (k + 0.5) * side};
        s.particles.push_back(p);
      }
  Footprint cube;
  cube.boxes.push_back({{}, {side / 2, side / 2, side / 2}, Quat{}});
  const auto fp = place_footprints(s, {cube});
  CollapseSetup setup;
  setup.initial_length = 0.1;
  setup.box_length = 0.4;
  setup.width = 0.04;
  setup.particle_size = side;
  const CollapseMeasures m = measure_collapse(s, fp, s, fp, setup);
  EXPECT_EQ(m.regime.regime, Regime::Stable);
  EXPECT_NEAR(m.initial_height.mean, 0.15, 1e-12);
  EXPECT_NEAR(m.aspect_ratio, 1.5, 1e-9);
  EXPECT_NEAR(m.runout_ratio, 0.0, setup.pixel / setup.initial_length);
  EXPECT_NEAR(m.height_ratio, 1.0, 1e-12);
  EXPECT_NEAR(m.centre_ratio, 0.0, 1e-12);
}

}  // namespace
}  // namespace talus::collapse
