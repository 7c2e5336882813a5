// The dissipation-free limit (Weinhart et al. 2012, Appendix A, Fig. 15): with gamma = 0 and
// mu -> infinity an oblique collision conserves kinetic plus elastic energy, and the elastic
// tangential spring stays orthogonal to the normal (Appendix B).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "talus/world/world.h"
#include "test_world_helpers.h"

namespace talus {
namespace {

struct EnergyRecord {
  double worst_drift = 0;      ///< max |E - E0| / E0
  double worst_normal_part = 0;  ///< max |delta_t . n| / |delta_t|
  double peak_tangential = 0;  ///< J, largest tangential elastic energy (the spring did load)
};

EnergyRecord oblique_collision(TangentialModel model) {
  WorldSettings s;
  s.domain = {{-5, -5, -5}, {5, 5, 5}};
  s.gravity = {};
  s.tangential_model = model;
  ContactParams c;
  c.normal_stiffness = 2e5;
  c.tangential_stiffness = 2.0 / 7.0 * 2e5;
  c.friction = 1e12;  // mu -> infinity: the spring never slips
  const double tc = std::numbers::pi / std::sqrt(2e5 / 0.5);
  s.time_step = tc / 2000;
  World w(s);
  w.contacts().resize(1, 1);
  w.contacts().set_pair(0, 0, c);
  const Vec3 axis{std::cos(0.5), std::sin(0.5), 0.1};
  const Vec3 n = axis / norm(axis);
  ParticleInit a = testing::sphere(n * -0.5005, 0.5, 6 / std::numbers::pi);
  a.velocity = {1, 0.2, 0};
  a.angular_velocity = {0, 3, -5};
  w.add_particle(a);
  ParticleInit b = testing::sphere(n * 0.5005, 0.5, 6 / std::numbers::pi);
  b.velocity = {-1, -0.1, 0.1};
  b.angular_velocity = {2, 0, 1};
  w.add_particle(b);

  EnergyRecord r;
  double e0 = -1;
  for (int k = 0; k < 6000; ++k) {
    w.step();
    const Diagnostics d = w.diagnostics();
    const double e = d.kinetic() + d.elastic();
    if (e0 < 0) e0 = e;
    r.worst_drift = std::max(r.worst_drift, std::abs(e - e0) / e0);
    r.peak_tangential = std::max(r.peak_tangential, d.elastic_tangential);
    const PairList& list = w.pair_list();
    if (list.entries() == 1 && !list.memory.spring.empty()) {
      const auto& p = w.particles();
      const Vec3 normal = normalized_or_zero(p.position[0] - p.position[list.neighbor(0)]);
      const Vec3 spring = list.memory.spring[0];
      if (norm(spring) > 1e-9) r.worst_normal_part = std::max(r.worst_normal_part, std::abs(dot(spring, normal)) / norm(spring));
    }
  }
  return r;
}

TEST(EnergyConservation, ElasticSpringObliqueCollision) {
  const EnergyRecord r = oblique_collision(TangentialModel::elastic_spring);
  std::printf("elastic_spring: energy drift %.3g, normal part %.3g\n", r.worst_drift, r.worst_normal_part);
  EXPECT_GT(r.peak_tangential, 1e-4);  // the tangential spring took part in the exchange
  EXPECT_LT(r.worst_drift, 1e-4);
  // Eq. (9) keeps the spring tangential up to the forward-Euler error of one contact.
  EXPECT_LT(r.worst_normal_part, 1e-3);
}

TEST(EnergyConservation, MemoryModelObliqueCollision) {
  const EnergyRecord r = oblique_collision(TangentialModel::memory);
  std::printf("memory: energy drift %.3g, normal part %.3g\n", r.worst_drift, r.worst_normal_part);
  EXPECT_GT(r.peak_tangential, 1e-4);
  EXPECT_LT(r.worst_drift, 1e-4);
  EXPECT_LT(r.worst_normal_part, 1e-9);  // the rotation of Eq. (8) is exact
}

}  // namespace
}  // namespace talus
