// Moving walls follow their prescribed motion, and pouring adds particles without overlaps.
#include <gtest/gtest.h>

#include "talus/scenario/pouring.h"
#include "talus/world/world.h"
#include "test_world_helpers.h"

namespace talus {
namespace {

TEST(Walls, GateAcceleratesToItsTopSpeed) {
  // Huet et al. 2021, Sec. III A: 43 m/s^2 up to 3 m/s, reached after 3/43 s.
  WallMotion m;
  m.kind = WallMotion::Kind::accelerated;
  m.acceleration = 43;
  m.top_speed = 3;
  m.start_time = 0.01;
  EXPECT_DOUBLE_EQ(m.speed(0.005), 0.0);
  EXPECT_DOUBLE_EQ(m.speed(0.01 + 0.05), 43 * 0.05);
  EXPECT_DOUBLE_EQ(m.speed(1.0), 3.0);
  const double t_top = 3.0 / 43;
  EXPECT_NEAR(m.displacement(0.01 + t_top), 0.5 * 43 * t_top * t_top, 1e-15);
  EXPECT_NEAR(m.displacement(0.01 + t_top + 0.1), 0.5 * 43 * t_top * t_top + 0.3, 1e-15);
}

TEST(Walls, RemovedWallReleasesTheParticle) {
  WorldSettings s;
  s.domain = {{-1, -1, -1}, {1, 1, 1}};
  s.gravity = {-9.81, 0, 0};  // pressed against a wall at x = 0 that disappears at t = 0.01
  s.time_step = 1e-5;
  World w(s);
  w.contacts().resize(1, 1);
  const ContactParams c = testing::glass_contact(0.005, 2500, 0.5, 1.0);
  w.contacts().set_pair(0, 0, c);
  w.contacts().set_wall(0, 0, c);
  Wall gate;
  gate.name = "gate";
  gate.normal = {1, 0, 0};
  gate.motion.kind = WallMotion::Kind::removed;
  gate.motion.start_time = 0.01;
  w.add_wall(gate);
  w.add_particle(testing::sphere({0.005, 0, 0}, 0.005, 2500));
  w.run(900);
  EXPECT_GT(-w.wall_force(0).x, 0.0);  // the wall holds the particle's weight
  EXPECT_NEAR(w.particles().velocity[0].x, 0.0, 1e-3);
  w.run(2000);  // 0.02 s after removal: free fall
  EXPECT_NEAR(w.particles().velocity[0].x, -9.81 * (w.time() - 0.01), 0.02);
  EXPECT_EQ(w.wall_force(0).x, 0.0);
}

// A 5 x 5 x 20 cm box of glass beads with a floor, for the pours below.
class Pouring : public ::testing::Test {
 protected:
  static WorldSettings settings() {
    WorldSettings s;
    s.domain = {{0, 0, 0}, {0.05, 0.05, 0.2}};
    s.time_step = 1e-5;
    return s;
  }
  Pouring() : w(settings()) {
    w.contacts().resize(1, 1);
    const ContactParams c = testing::glass_contact(0.002, 2500, 0.5, 1.0);
    w.contacts().set_pair(0, 0, c);
    w.contacts().set_wall(0, 0, c);
    Wall floor;
    floor.normal = {0, 0, 1};
    w.add_wall(floor);
  }
  World w;
};

TEST_F(Pouring, BatchesArriveWithoutOverlaps) {
  PourSpec spec;
  spec.density = 2500;
  spec.radius_min = 0.0015;
  spec.radius_max = 0.002;
  spec.region_lo = {0.005, 0.005, 0.1};
  spec.region_hi = {0.045, 0.045, 0.15};
  spec.total = 60;
  spec.batch = 20;
  spec.interval = 0.02;
  talus::Pouring pour(spec, 5);
  while (w.time() < 0.1) {
    pour.pour_due(w);
    w.step();
    EXPECT_LT(w.diagnostics().max_overlap_ratio, 0.2);
  }
  EXPECT_EQ(pour.poured(), 60u);
  EXPECT_EQ(w.particles().owned, 60u);
}

// A pour region that starts below the floor's reach: no particle is poured into the floor.
TEST_F(Pouring, KeepsClearOfWalls) {
  PourSpec spec;
  spec.density = 2500;
  spec.radius_min = spec.radius_max = 0.002;
  spec.region_lo = {0.005, 0.005, 0.0};  // centres drawn from z = 0 up: half would cut the floor
  spec.region_hi = {0.045, 0.045, 0.008};
  spec.total = 20;
  spec.batch = 20;
  spec.interval = 1;
  talus::Pouring pour(spec, 5);
  EXPECT_GT(pour.pour_due(w), 0u);
  for (std::size_t i = 0; i < w.particles().owned; ++i) EXPECT_GE(w.particles().position[i].z, 0.002) << i;
}

}  // namespace
}  // namespace talus
