// The vector form of the elastic-spring law (world/sphere_elastic_batch.cpp) against the
// scalar law it restates (contact_law.h through sphere_contact.h), contact by contact.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "talus/world/sphere_contact.h"
#include "talus/world/sphere_elastic_batch.h"

namespace talus {
namespace {

double rel_diff(const Vec3& a, const Vec3& b, double scale) { return norm(a - b) / scale; }

// The three species pairs of the tests: one with mass-scaled damping and one with k_t = 0 (the
// spring is then reset to zero when sliding).
ContactTable three_pairs(const ContactParams& a) {
  ContactTable table;
  table.resize(2, 0);
  ContactParams b = a;
  b.normal_damping = {0, 40, 3};
  b.tangential_damping = {1, 20, 0};
  b.friction = 0.3;
  ContactParams c = a;
  c.tangential_stiffness = 0;
  c.tangential_damping.coefficient = 80;
  table.set_pair(0, 0, a);
  table.set_pair(0, 1, b);
  table.set_pair(1, 1, c);
  return table;
}

ContactParams linear_params() {
  ContactParams a;
  a.normal_stiffness = 2e5;
  a.normal_damping.coefficient = 50;
  a.tangential_stiffness = 2e5 * 2 / 7;
  a.tangential_damping.coefficient = 50;
  a.friction = 0.5;
  return a;
}

// Random touching pairs of polydisperse spheres with random motions and springs, so that some
// contacts stick and others slide.
template <bool kGrown>
void expect_batch_matches_scalar(const ContactTable& table) {
  ASSERT_EQ(batch_law(table), kGrown ? BatchLaw::grown : BatchLaw::linear);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  const auto rand_vec = [&](double s) { return Vec3{u(rng), u(rng), u(rng)} * s; };
  constexpr int kBodies = 2 * ContactBatch::kSize;  // contact k: bodies 2k and 2k + 1
  std::vector<Vec3> position(kBodies), velocity(kBodies), spin(kBodies);
  std::vector<double> radius(kBodies), inv_mass(kBodies);
  std::vector<std::int32_t> species(kBodies);
  for (int k = 0; k < kBodies; ++k) {
    radius[k] = 0.5 + 0.1 * u(rng);
    inv_mass[k] = k % 17 == 0 ? 0.0 : 1.0 / (1.0 + 0.3 * u(rng));  // some fixed base particles
    species[k] = k % 3 == 0 ? 1 : 0;
    velocity[k] = rand_vec(2.0);
    spin[k] = rand_vec(4.0);
  }
  const double dt = 1e-4;
  // Several batch sizes, full and partial (padding lanes).
  int slid = 0, stuck = 0;
  for (const std::uint32_t count : {1u, 3u, 8u, 13u, ContactBatch::kSize}) {
    ContactBatch batch;
    std::vector<Vec3> spring_batch, spring_scalar;
    std::vector<ContactResult> expected;
    for (std::uint32_t k = 0; k < count; ++k) {
      const std::uint32_t i = 2 * k + (k % 2), j = 2 * k + 1 - (k % 2);
      // j placed touching i at a random overlap up to 2 % of the reach.
      const double reach = radius[i] + radius[j];
      const Vec3 dir = normalized_or_zero(rand_vec(1.0));
      position[i] = rand_vec(10.0);
      position[j] = position[i] - dir * (reach * (1 - 0.02 * (0.5 + 0.5 * u(rng))));
      const Vec3 d = position[i] - position[j];
      const Vec3 s0 = rand_vec(k % 2 ? 0.1 : 1e-6);  // large springs slide, small ones stick
      batch.entry[k] = k;
      batch.i[k] = i;
      batch.j[k] = j;
      spring_batch.push_back(s0);
      spring_scalar.push_back(s0);
      const ContactMotion m{velocity[i], spin[i], velocity[j], spin[j]};
      const ContactHistoryRef h{&spring_scalar.back(), nullptr, nullptr};
      expected.push_back(sphere_contact<TangentialModel::elastic_spring>(
          d, norm2(d), radius[i], radius[j], m, table.pair(species[i], species[j]), 1.0 / (inv_mass[i] + inv_mass[j]),
          dt, h));
    }
    batch.count = static_cast<std::uint32_t>(expected.size());
    sphere_elastic_batch<kGrown>(batch, position.data(), velocity.data(), spin.data(), radius.data(), inv_mass.data(), species.data(), table,
                         spring_batch.data(), dt);
    for (std::uint32_t k = 0; k < batch.count; ++k) {
      // Scales: the force and torque magnitudes of this contact. The two forms differ only by
      // the rounding of reordered operations (fused multiply-adds in the vector loop).
      const double f = std::max(norm(expected[k].force_on_i), 1e-300);
      const double r = radius[batch.i[k]] + radius[batch.j[k]];
      EXPECT_LT(rel_diff(batch.force_on_i(k), expected[k].force_on_i, f), 1e-12) << "contact " << k;
      EXPECT_LT(rel_diff(batch.torque_i(k), expected[k].torque_i, f * r), 1e-12) << "contact " << k;
      EXPECT_LT(rel_diff(batch.torque_j(k), expected[k].torque_j, f * r), 1e-12) << "contact " << k;
      const double s = std::max(norm(spring_scalar[k]), 1e-300);
      EXPECT_LT(rel_diff(spring_batch[k], spring_scalar[k], s), 1e-12) << "contact " << k;
      const Vec3 normal = normalized_or_zero(position[batch.i[k]] - position[batch.j[k]]);
      const double fn = std::abs(dot(expected[k].force_on_i, normal));
      const double ft = norm(expected[k].force_on_i - dot(expected[k].force_on_i, normal) *
                                                          normal);
      const double mu = table.pair(species[batch.i[k]], species[batch.j[k]]).friction;
      (ft > (1 - 1e-9) * mu * fn ? slid : stuck) += 1;
    }
  }
  std::printf("elastic batch: %d sliding and %d sticking contacts agree with the scalar law\n", slid, stuck);
  // Both branches of the Coulomb truncation were exercised.
  EXPECT_GT(slid, 5);
  EXPECT_GT(stuck, 5);
}


TEST(SphereElasticBatch, MatchesTheScalarLawContactByContact) { expect_batch_matches_scalar<false>(three_pairs(linear_params())); }

TEST(SphereElasticBatch, ClampedLinearMatchesTheScalarLaw) {
  ContactParams a = linear_params();
  a.clamp = NormalClamp::clamped;
  expect_batch_matches_scalar<false>(three_pairs(a));
}

// Hertz-Mindlin with Tsuji's dashpots: every coefficient grows with the contact radius.
TEST(SphereElasticBatch, HertzMindlinMatchesTheScalarLaw) {
  ContactParams a = linear_params();
  a.normal_law = normal_law_index<HertzNormal>();
  a.damping_scaling = DampingScaling::tsuji;
  a.tangential_law = TangentialStiffness::mindlin;
  a.normal_stiffness = 2e7;
  a.tangential_stiffness = 1.6e7;
  expect_batch_matches_scalar<true>(three_pairs(a));
}

// Pairs under different laws cannot share a batch.
TEST(SphereElasticBatch, MixedLawsRunContactByContact) {
  ContactTable table = three_pairs(linear_params());
  ContactParams hertz = table.pair(1, 1);
  hertz.normal_law = normal_law_index<HertzNormal>();
  table.set_pair(1, 1, hertz);
  EXPECT_EQ(batch_law(table), BatchLaw::none);
}

}  // namespace
}  // namespace talus
