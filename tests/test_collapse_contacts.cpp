// Coordination number, wall contact counts and wall load shares of a hand-built contact list.
#include <gtest/gtest.h>

#include "talus/analysis/collapse_contacts.h"

namespace talus::collapse {
namespace {

// Walls: 0 ground, 1 and 2 side walls, 3 gate, 4 back wall (no role).
const WallRoles kRoles{{0}, {1, 2}, {3}};

ContactRecord pp(int i, int j, Vec3 point = {}) {
  ContactRecord c;
  c.i = i;
  c.j = j;
  c.point = point;
  c.force = {0, 0, 1};
  return c;
}

ContactRecord wall(int i, int w, Vec3 point, Vec3 force = {}) {
  ContactRecord c;
  c.i = i;
  c.wall = w;
  c.point = point;
  c.force = force;
  return c;
}

// Column L0 = 0.1, H0 = 0.2. Particles 0, 1 near the back bottom; 2 near the gate, low;
// 3 near the gate, high; 4 a rattler near the back top; 5 fixed (not counted).
Snapshot column() {
  Snapshot s;
  s.gravity = {0, 0, -10};
  const Vec3 at[] = {{0.02, 0.02, 0.01}, {0.03, 0.02, 0.03}, {0.08, 0.02, 0.02},
                     {0.09, 0.02, 0.15}, {0.02, 0.02, 0.18}, {0.5, 0.5, 0.5}};
  for (int k = 0; k < 6; ++k) {
    ParticleRecord p;
    p.id = static_cast<std::uint32_t>(k);
    p.mass = 0.1;
    p.position = at[k];
    p.fixed = (k == 5);
    s.particles.push_back(p);
  }
  s.contacts = {
      pp(0, 1), pp(1, 0), pp(0, 1),  // one pair touching at three points, listed both ways round
      pp(1, 2), pp(2, 3), pp(3, 2),  // 2-3 touch at two points
      pp(0, 5),                      // contact with a fixed particle still counts for 0
      wall(0, 0, {0.02, 0.02, 0}), wall(2, 0, {0.08, 0.02, 0}),
      wall(0, 1, {0.02, 0, 0.01}), wall(3, 2, {0.09, 0.04, 0.15}), wall(3, 1, {0.09, 0, 0.16}),
      wall(2, 3, {0.1, 0.02, 0.02}), wall(3, 3, {0.1, 0.02, 0.15}),
      wall(0, 4, {0, 0.02, 0.01}),
  };
  return s;
}

TEST(CollapseContacts, WholeColumnCountsEachPairOnceAndEachPoint) {
  const ContactStatistics st = contact_statistics(column(), kRoles);
  EXPECT_EQ(st.particles, 5);
  // Distinct neighbours: 0:{1,5} 1:{0,2} 2:{1,3} 3:{2} 4:{} -> 7.
  EXPECT_EQ(st.neighbours, 7);
  EXPECT_DOUBLE_EQ(st.coordination, 7.0 / 5);
  // Points: 0: 3 + 1, 1: 3 + 1, 2: 1 + 2, 3: 2, 4: 0 -> 13.
  EXPECT_EQ(st.contact_points, 13);
  EXPECT_DOUBLE_EQ(st.coordination_points, 13.0 / 5);
  EXPECT_EQ(st.ground, 2);
  EXPECT_EQ(st.side, 3);
  EXPECT_EQ(st.gate, 2);
}

TEST(CollapseContacts, TableThreeRegionsNearTheGateAndItsTop) {
  const Snapshot s = column();
  const TableThreeRegions r = table_three_regions(0.1, 0.2);

  const ContactStatistics half = contact_statistics(s, kRoles, r.near_gate);
  EXPECT_EQ(half.particles, 2);       // 2 and 3
  EXPECT_EQ(half.neighbours, 3);      // 2:{1,3} 3:{2}
  EXPECT_EQ(half.contact_points, 5);  // 2: 1 + 2, 3: 2
  EXPECT_DOUBLE_EQ(half.coordination, 1.5);
  EXPECT_EQ(half.ground, 1);
  EXPECT_EQ(half.side, 2);
  EXPECT_EQ(half.gate, 2);

  const ContactStatistics quarter = contact_statistics(s, kRoles, r.near_gate_top);
  EXPECT_EQ(quarter.particles, 1);    // 3
  EXPECT_EQ(quarter.neighbours, 1);
  EXPECT_EQ(quarter.contact_points, 2);
  EXPECT_EQ(quarter.ground, 0);       // as in Table III: no ground contact up there
  EXPECT_EQ(quarter.side, 2);
  EXPECT_EQ(quarter.gate, 1);
}

TEST(CollapseContacts, SideWallsCarryTheirShareOfTheWeight) {
  Snapshot s = column();
  s.contacts.clear();
  const double weight = 5 * 0.1 * 10;  // the fixed particle does not count
  s.contacts.push_back(wall(0, 0, {}, {0.1, 0, 0.8 * weight}));
  s.contacts.push_back(wall(3, 1, {}, {0, 0.3, 0.05 * weight}));
  s.contacts.push_back(wall(3, 2, {}, {0, -0.3, 0.05 * weight}));
  s.contacts.push_back(wall(2, 3, {}, {-0.2, 0, 0.1 * weight}));
  s.contacts.push_back(pp(0, 1));
  const WallLoadShares w = wall_load_shares(s, kRoles);
  EXPECT_NEAR(w.ground, 0.8, 1e-12);
  EXPECT_NEAR(w.side, 0.1, 1e-12);
  EXPECT_NEAR(w.gate, 0.1, 1e-12);
}

}  // namespace
}  // namespace talus::collapse
