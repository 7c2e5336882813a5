// A cube and a cross resting on a plane (memory contact model): static, the normal force equals
// the weight, residual speeds vanish; single contact point (Huet et al. 2021) and manifold.
#include <gtest/gtest.h>

#include <cstdio>

#include "talus/contact/parameter_procedure.h"
#include "talus/scenario/rigid_body_type.h"
#include "talus/shape/convex_shape.h"
#include "talus/world/world.h"

namespace talus {
namespace {

struct RestResult {
  double weight_ratio = 0;  ///< wall normal force / weight
  double max_speed = 0;     ///< m/s
  double max_spin = 0;      ///< rad/s
};

RestResult rest_on_plane(const CompositeShape& shape, double density, bool manifold, double height, double duration) {
  WorldSettings s;
  s.domain = {{-1, -1, -1}, {1, 1, 1}};
  s.gravity = {0, 0, -9.81};
  s.contact_manifold = manifold;
  const RigidBodyType type = make_rigid_body_type(shape, density);
  ContactParams c;
  c.normal_stiffness = 1e4;
  c.normal_damping.coefficient = params::normal_damping(c.normal_stiffness, type.mass, 0.3);
  c.tangential_stiffness = 2.0 / 7.0 * c.normal_stiffness;
  c.tangential_damping = c.normal_damping;
  c.friction = 0.5;
  s.time_step = params::contact_time(c.normal_stiffness, type.mass / 4, 0.3) / 50;  // a quarter: the stiffness of one of four points
  World w(s);
  w.contacts().resize(1, 1);
  w.contacts().set_pair(0, 0, c);
  w.contacts().set_wall(0, 0, c);
  Wall floor;
  floor.name = "floor";
  floor.normal = {0, 0, 1};
  w.add_wall(floor);
  const int index = w.add_shape(type.shape);
  // Slightly tilted so that it lands on an edge and has to settle.
  w.add_particle(rigid_particle(type, index, {0, 0, height}, Quat::from_axis_angle({1, 0.3, 0}, 0.02), 0));
  while (w.time() < duration) w.run(1000);
  const Diagnostics d = w.diagnostics();
  return {-w.wall_force(0).z / (-type.mass * s.gravity.z), d.max_speed, d.max_angular_speed};  // wall_force: on the wall
}

// The single point of Huet et al. 2021 (Sec. II B) wanders over the bottom face: the cube
// rocks and never comes to rest. This is why the manifold exists.
TEST(RigidResting, CubeSinglePointKeepsRocking) {
  const CompositeShape cube = [] {
    CompositeShape c;
    c.add(make_box({0.005, 0.005, 0.005}, 2e-4), Pose{});
    return c;
  }();
  const RestResult r = rest_on_plane(cube, 1000, false, 0.0052, 1.0);
  std::printf("cube, one point: F/W - 1 = %.3g, speed %.3g m/s, spin %.3g rad/s\n", r.weight_ratio - 1, r.max_speed, r.max_spin);
  EXPECT_GT(r.max_speed, 1e-8);
}

TEST(RigidResting, CubeManifold) {
  CompositeShape cube;
  cube.add(make_box({0.005, 0.005, 0.005}, 2e-4), Pose{});
  const RestResult r = rest_on_plane(cube, 1000, true, 0.0052, 1.0);
  std::printf("cube, manifold: F/W - 1 = %.3g, speed %.3g m/s, spin %.3g rad/s\n", r.weight_ratio - 1, r.max_speed, r.max_spin);
  EXPECT_NEAR(r.weight_ratio, 1.0, 1e-3);
  EXPECT_LT(r.max_speed, 1e-10);
}

TEST(RigidResting, CrossManifold) {
  const RestResult r = rest_on_plane(make_huet_cross(27e-3, 2e-3, 3e-3, 1e-4), 770, true, 0.0016, 1.0);
  std::printf("cross, manifold: F/W - 1 = %.3g, speed %.3g m/s, spin %.3g rad/s\n", r.weight_ratio - 1, r.max_speed, r.max_spin);
  EXPECT_NEAR(r.weight_ratio, 1.0, 1e-3);
  EXPECT_LT(r.max_speed, 1e-10);
}

}  // namespace
}  // namespace talus
