// Fabric of branch vectors projected on the xz plane (Huet et al. 2021, Figs. 16-17).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "talus/analysis/fabric.h"

namespace talus {
namespace {

// A centre particle touched by m neighbours at evenly spread angles in the xz plane, each with
// an arbitrary y offset (the projection ignores it), plus contacts with walls (excluded).
Snapshot star(int m) {
  Snapshot s;
  s.particles.push_back({});
  for (int k = 0; k < m; ++k) {
    const double theta = (k + 0.5) * 2 * std::numbers::pi / m;
    ParticleRecord p;
    p.position = {std::cos(theta), 0.3 * std::sin(3.0 * k), std::sin(theta)};
    s.particles.push_back(p);
    ContactRecord c;
    c.i = 0;
    c.j = k + 1;
    s.contacts.push_back(c);
    ContactRecord w;
    w.i = k + 1;
    w.wall = 0;
    s.contacts.push_back(w);
  }
  return s;
}

TEST(CollapseFabric, IsotropicBranchVectorsGiveAFlatHistogram) {
  const int bins = 18;
  const Snapshot s = star(4 * bins);
  const FabricHistogram h = fabric_angle_histogram(s, bins);
  EXPECT_EQ(h.samples, static_cast<std::size_t>(4 * bins));
  double integral = 0;
  for (int k = 0; k < bins; ++k) {
    EXPECT_NEAR(h.density[k], 1.0 / std::numbers::pi, 1e-12) << "bin " << k;
    integral += h.density[k] * (h.edges[k + 1] - h.edges[k]);
  }
  EXPECT_NEAR(integral, 1.0, 1e-12);
  const PlaneFabric f = fabric_xz(s);
  EXPECT_NEAR(f.anisotropy, 0.0, 1e-12);
  EXPECT_NEAR(f.xx + f.zz, 1.0, 1e-12);
  const FabricTensor phi = fabric_tensor(s);
  EXPECT_NEAR(phi[0][0] + phi[1][1] + phi[2][2], 1.0, 1e-12);
}

TEST(CollapseFabric, HorizontalChainIsAllAtZeroAndVerticalAtHalfPi) {
  Snapshot s;
  for (int k = 0; k < 4; ++k) {
    ParticleRecord p;
    p.position = {0.01 * k, 0, 0};
    s.particles.push_back(p);
  }
  // A horizontal chain 0-1-2 and one vertical contact 3 above 2, listed from the top (j below i).
  s.particles[3].position = {0.02, 0, 0.01};
  for (auto [i, j] : {std::pair{0, 1}, {2, 1}, {3, 2}}) {
    ContactRecord c;
    c.i = i;
    c.j = j;
    s.contacts.push_back(c);
  }
  const FabricHistogram h = fabric_angle_histogram(s, 4);
  const double w = std::numbers::pi / 4;
  // 0->1 is at 0 and 2->1 at pi (folds into the last bin); 3->2 points down: -pi/2 folds to pi/2.
  EXPECT_NEAR(h.density[0], 1.0 / 3 / w, 1e-12);
  EXPECT_NEAR(h.density[2], 1.0 / 3 / w, 1e-12);
  EXPECT_NEAR(h.density[3], 1.0 / 3 / w, 1e-12);
  const PlaneFabric f = fabric_xz(s);
  EXPECT_NEAR(f.xx, 2.0 / 3, 1e-12);
  EXPECT_NEAR(f.anisotropy, 2.0 / 3, 1e-12);
  EXPECT_NEAR(f.direction, 0.0, 1e-9);
}

}  // namespace
}  // namespace talus
