// Force network segments and the PDF of F_c / <F_c> (Huet et al. 2021, Fig. 15).
#include <gtest/gtest.h>

#include <numeric>
#include <random>

#include "talus/analysis/force_network.h"
#include "talus/analysis/force_network_pdf.h"

namespace talus {
namespace {

ContactRecord contact(int i, int j, Vec3 force) {
  ContactRecord c;
  c.i = i;
  c.j = j;
  c.force = force;
  return c;
}

Snapshot three_particles() {
  Snapshot s;
  for (int k = 0; k < 3; ++k) {
    ParticleRecord p;
    p.position = {0.01 * k, 0, 0};
    s.particles.push_back(p);
  }
  s.contacts = {contact(0, 1, {-3, 0, 0}), contact(1, 0, {0, 4, 0}),  // two points of one pair
                contact(1, 2, {0, 0, 2}), contact(2, -1, {0, 0, 7})};
  s.contacts[3].wall = 0;
  return s;
}

TEST(CollapseForceNetwork, SegmentsJoinCentresPerPointOrPerPair) {
  const Snapshot s = three_particles();
  const auto each = force_network(s);
  ASSERT_EQ(each.size(), 3u);  // the wall contact has no second centre
  EXPECT_DOUBLE_EQ(each[0].force, 3.0);
  EXPECT_EQ(each[1].from, s.particles[1].position);
  EXPECT_EQ(each[1].to, s.particles[0].position);

  const auto merged = force_network(s, PairPoints::MergePerPair);
  ASSERT_EQ(merged.size(), 2u);
  // Force on 0 from 1: (-3, 0, 0) plus the reverse of (0, 4, 0), which was the force on 1.
  EXPECT_DOUBLE_EQ(merged[0].force, 5.0);
  EXPECT_EQ(merged[0].points, 2);
  EXPECT_EQ(contact_force_magnitudes(s, PairPoints::EachPoint, true).size(), 4u);
}

TEST(CollapseForceNetwork, PeriodicSegmentsTakeTheNearestImage) {
  Snapshot s = three_particles();
  s.periodic[0] = true;
  s.domain_min = {0, 0, 0};
  s.domain_max = {0.025, 1, 1};
  const Vec3 b = branch_vector(s, 0, 2);  // 0.02 apart, 0.005 through the boundary
  EXPECT_NEAR(b.x, -0.005, 1e-15);
}

std::vector<double> exponential_forces(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::exponential_distribution<double> e(2.0);
  std::vector<double> f(n);
  for (double& x : f) x = e(rng);
  return f;
}

double integral(const ForcePdf& pdf) {
  double sum = 0;
  for (std::size_t k = 0; k < pdf.density.size(); ++k) sum += pdf.density[k] * (pdf.edges[k + 1] - pdf.edges[k]);
  return sum;
}

double histogram_mean(const ForcePdf& pdf) {
  double sum = 0;
  for (std::size_t k = 0; k < pdf.density.size(); ++k)
    sum += pdf.centres[k] * pdf.density[k] * (pdf.edges[k + 1] - pdf.edges[k]);
  return sum;
}

TEST(CollapseForcePdf, LinearBinsIntegrateToOneWithUnitMean) {
  const auto forces = exponential_forces(20000, 5);
  const ForcePdf pdf = force_pdf_linear(forces, 200);
  EXPECT_NEAR(integral(pdf), 1.0, 1e-12);
  EXPECT_EQ(pdf.outside, 0u);
  const double mean = std::accumulate(forces.begin(), forces.end(), 0.0) / forces.size();
  EXPECT_DOUBLE_EQ(pdf.mean_force, mean);
  // The mean of F/<F> is 1 by construction; the binned mean is off by at most half a bin.
  EXPECT_NEAR(histogram_mean(pdf), 1.0, 0.5 * (pdf.edges[1] - pdf.edges[0]));
  // An exponential law of unit mean has density exp(-x): check the first bins.
  EXPECT_NEAR(pdf.density[2], std::exp(-pdf.centres[2]), 0.1);
}

TEST(CollapseForcePdf, LogBinsIntegrateToOneAndSetZerosApart) {
  auto forces = exponential_forces(20000, 9);
  const ForcePdf pdf = force_pdf_log(forces, 60);
  EXPECT_NEAR(integral(pdf), 1.0, 1e-12);
  EXPECT_NEAR(histogram_mean(pdf), 1.0, 0.02);
  EXPECT_NEAR(pdf.centres[0], std::sqrt(pdf.edges[0] * pdf.edges[1]), 1e-15);

  forces.push_back(0.0);  // a zero force has no place on a log axis
  const ForcePdf with_zero = force_pdf_log(forces, 60);
  EXPECT_EQ(with_zero.outside, 1u);
  EXPECT_NEAR(integral(with_zero), 1.0 - 1.0 / forces.size(), 1e-12);
}

}  // namespace
}  // namespace talus
