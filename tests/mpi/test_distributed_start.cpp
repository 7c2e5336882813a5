// A run built on rank 0 alone and handed out (ScenarioLimits::particles_on_first_rank) against
// the same run built whole on every rank: no other rank ever holds a particle it does not own,
// and the run is the same to the bit.
#include <gtest/gtest.h>

#include <map>

#include "talus/io/scenario_file.h"
#include "talus/parallel/communicator.h"
#include "talus/scenario/scenario.h"

namespace talus {
namespace {

// A small chute of seed 001's kind (a rough base, a layer at volume fraction 0.3), and a small
// dam break of spheres poured behind a gate: one built at once, one in batches.
constexpr const char* kChute = R"(
[run]
end_time = 1.0
steps_per_contact = 10
[chute]
length = 12.0
width = 6.0
fill_height = 4.0
angle = 26.0
[contact]
model = "elastic_spring"
normal_stiffness = 2e5
normal_damping_rate = 50
tangential_stiffness_ratio = 0.2857142857142857
tangential_damping_rate = 50
friction = 0.5
)";

Scenario load(const char* text, bool on_first_rank) {
  io::ScenarioFile file = io::ScenarioFile::from_string(text, "start.toml");
  ScenarioLimits limits;
  limits.particles_on_first_rank = on_first_rank;
  return load_scenario(file, limits);
}

std::map<std::uint32_t, Vec3> owned_positions(const World& w) {
  std::map<std::uint32_t, Vec3> out;
  const ParticleStore& p = w.particles();
  for (std::size_t i = 0; i < p.owned; ++i) out[p.gid[i]] = p.position[i];
  return out;
}

TEST(DistributedStart, BuiltOnTheFirstRankSameAsBuiltEverywhere) {
  const Communicator& comm = Communicator::world();
  Scenario everywhere = load(kChute, false);
  Scenario first = load(kChute, true);
  World& a = *everywhere.world;
  World& b = *first.world;
  const std::size_t n = a.particles().owned;
  ASSERT_GT(n, 400u);  // 288 flowing spheres on about 150 of the base
  EXPECT_EQ(b.particles_added(), n);
  EXPECT_EQ(b.particles().owned, comm.rank() == 0 ? n : 0u);
  EXPECT_EQ(b.particles().position.capacity() > 0, comm.rank() == 0);  // nothing reserved elsewhere
  a.distribute(comm);
  b.distribute(comm);
  EXPECT_EQ(b.rank_grid().counts(), a.rank_grid().counts());
  EXPECT_EQ(b.rank_grid().slab_axis, a.rank_grid().slab_axis);
  for (int axis = 0; axis < 3; ++axis) {  // rebalancing later moves the cuts alike only if all of these agree
    const SlabDecomposition &sa = a.rank_grid().axes[axis], &sb = b.rank_grid().axes[axis];
    EXPECT_EQ(sb.cut, sa.cut);
    EXPECT_EQ(sb.min_width, sa.min_width) << "axis " << axis;
    EXPECT_EQ(sb.rebalance, sa.rebalance) << "axis " << axis;
    EXPECT_EQ(sb.index, sa.index) << "axis " << axis;
  }
  EXPECT_EQ(comm.sum(static_cast<std::uint64_t>(b.owned_count())), n);
  // Each rank owns the same particles, in the same order, so the steps are the same to the bit.
  ASSERT_EQ(b.owned_count(), a.owned_count());
  for (std::size_t i = 0; i < a.owned_count(); ++i) ASSERT_EQ(b.particles().gid[i], a.particles().gid[i]);
  a.run(4000);  // t = 2: the layer has fallen onto the base
  b.run(4000);
  EXPECT_GT(a.diagnostics().contacts, 5u);  // the first spheres have landed on the base
  const auto pa = owned_positions(a), pb = owned_positions(b);
  ASSERT_EQ(pb.size(), pa.size());
  for (const auto& [gid, x] : pa) {
    const auto it = pb.find(gid);
    ASSERT_NE(it, pb.end()) << "particle " << gid;
    EXPECT_EQ(it->second.x, x.x);
    EXPECT_EQ(it->second.y, x.y);
    EXPECT_EQ(it->second.z, x.z);
  }
  // Particles added later (pouring, insertion mid-run) go to their owners as before.
  EXPECT_FALSE(b.settings().particles_on_first_rank);
}

}  // namespace
}  // namespace talus
