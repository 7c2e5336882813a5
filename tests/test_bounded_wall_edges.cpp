// A rigid body or a sphere meeting the edge of a bounded wall (a plate): the contact must grow
// from zero as the body comes over the edge, so an elastic encounter gives back the energy it
// took. Before plates had edges, a part reaching under an edge was left alone until its deepest
// point came over the face, and then met the plane at its whole depth at once: a tetrapod
// sliding off a hopper's wall gained enough energy there to leave the domain.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "talus/scenario/rigid_body_type.h"
#include "talus/shape/convex_shape.h"
#include "talus/world/world.h"
#include "test_world_helpers.h"

namespace talus {
namespace {

constexpr double kRodRadius = 5e-4, kRodHalfLength = 2e-3;  // m, a tetrapod's arm
constexpr double kEdge = 0.01;                               // m, the plate's edge at x = +0.01

struct Encounter {
  double energy_before = 0, energy_after = 0;  ///< J, kinetic
  double vx_after = 0;                         ///< m/s
  double largest_overlap = 0;                  ///< m, over the encounter
};

// No gravity, and a step that resolves the contact times pi sqrt(m / k) below (about 1e-4 s).
WorldSettings settings(bool manifold) {
  WorldSettings s;
  s.domain = {{-0.05, -0.05, -0.05}, {0.05, 0.05, 0.05}};
  s.gravity = {0, 0, 0};
  s.contact_manifold = manifold;
  s.time_step = 2e-7;
  return s;
}

// A plate in the plane z = 0 facing +z, its edge at x = kEdge; elastic, frictionless contacts.
void add_plate(World& w) {
  ContactParams c;
  c.normal_stiffness = 1e4;
  c.tangential_stiffness = 0;
  c.friction = 0;
  w.contacts().resize(1, 1);
  w.contacts().set_pair(0, 0, c);
  w.contacts().set_wall(0, 0, c);
  Wall plate;
  plate.name = "plate";
  plate.normal = {0, 0, 1};
  plate.bounded = true;
  plate.axis_u = {1, 0, 0};
  plate.axis_v = cross(plate.normal, plate.axis_u);
  plate.half_extent_u = kEdge;
  plate.half_extent_v = 0.02;
  w.add_wall(plate);
}

// A rod (one cylinder, axis along x) tilted down towards the plate by `tilt`, its near end below
// the plate's face beyond the edge, moving at -vx towards the edge.
Encounter rod_meets_edge(bool manifold, double tilt, double vx) {
  CompositeShape rod;
  rod.add(make_cylinder(kRodRadius, kRodHalfLength, 1e-4), Pose{{}, Quat::from_axis_angle({0, 1, 0}, 0.5 * std::numbers::pi)});
  const RigidBodyType type = make_rigid_body_type(rod, 2500);
  World w(settings(manifold));
  add_plate(w);
  const int index = w.add_shape(type.shape);
  // Centre 0.2 mm in front of the face, 0.8 mm beyond the edge; the near end dips below it.
  ParticleInit body =
      rigid_particle(type, index, {kEdge + kRodHalfLength + 0.8e-3, 0, 2e-4}, Quat::from_axis_angle({0, 1, 0}, -tilt), 0);
  body.velocity = {-vx, 0, 0};
  w.add_particle(body);

  Encounter e;
  e.energy_before = w.diagnostics().kinetic();
  const double duration = 3e-3 / vx;  // long enough to close the 0.8 mm and come back
  while (w.time() < duration) {
    w.run(50);
    e.largest_overlap = std::max(e.largest_overlap, w.diagnostics().max_overlap_ratio * w.particles().radius[0]);
  }
  const Diagnostics d = w.diagnostics();
  e.energy_after = d.kinetic();
  e.vx_after = w.particles().velocity[0].x;
  return e;
}

TEST(BoundedWallEdges, RodReachingUnderAnEdgeBouncesOffIt) {
  for (const bool manifold : {false, true}) {
    const Encounter e = rod_meets_edge(manifold, 0.25, 0.1);
    std::printf("manifold %d: kinetic energy %.4g -> %.4g J, vx after %.4g m/s, largest overlap %.3g m\n", manifold,
                e.energy_before, e.energy_after, e.vx_after, e.largest_overlap);
    // It met the plate's end and turned back ...
    EXPECT_GT(e.vx_after, 0.0);
    EXPECT_GT(e.largest_overlap, 0.0);
    // ... as an elastic collision does: energy given back to within the step's truncation (a few
    // 1e-3 at 450 steps per contact time), not the 1/2 k delta^2 of a plane met 0.4 mm deep
    // (2e-3 J against 4e-8 J of motion).
    EXPECT_NEAR(e.energy_after / e.energy_before, 1.0, 0.02);
    // The overlap grew from zero and stayed a small fraction of the rod's radius.
    EXPECT_LT(e.largest_overlap, 0.1 * kRodRadius);
  }
}

// A sphere whose centre passes half a radius in front of the plate's face, coming from beyond the
// edge at -vx: it meets the rim where |x - c| = r, at (x - edge, z) = (cos 30, sin 30) r, and an
// elastic frictionless bounce off that point (the overlap stays a few 1e-3 of r, so the normal
// barely turns during it) reflects the velocity about n = (cos 30, 0, sin 30): v' = v - 2 (v.n) n.
// Caught at its centre coming over the face instead, it would meet the face 0.5 r deep at once.
TEST(BoundedWallEdges, SphereComingRoundAnEdgeReflectsOffTheRim) {
  constexpr double r = 1e-3, vx = 0.1;
  World w(settings(false));
  add_plate(w);
  ParticleInit ball = testing::sphere({kEdge + 2 * r, 0, 0.5 * r}, r, 2500);
  ball.velocity = {-vx, 0, 0};
  w.add_particle(ball);
  const double before = w.diagnostics().kinetic();
  double largest_overlap = 0;
  while (w.time() < 3 * r / vx) {
    w.run(50);
    largest_overlap = std::max(largest_overlap, w.diagnostics().max_overlap_ratio * r);
  }
  const Vec3 n{std::cos(std::numbers::pi / 6), 0, std::sin(std::numbers::pi / 6)};
  const Vec3 v0{-vx, 0, 0};
  const Vec3 expected = v0 - n * (2 * dot(v0, n));
  const Vec3 v = w.particles().velocity[0];
  std::printf("sphere off the rim: v = (%.5g, %.3g, %.5g) m/s, expected (%.5g, 0, %.5g); largest overlap %.3g r\n", v.x,
              v.y, v.z, expected.x, expected.z, largest_overlap / r);
  EXPECT_GT(largest_overlap, 0.0);
  EXPECT_LT(largest_overlap, 0.01 * r);
  // 1 % of the speed: the deflection of a linear spring of this stiffness differs from the hard
  // reflection by about the overlap over r (3e-3), and the step's truncation is smaller still.
  EXPECT_NEAR(v.x, expected.x, 0.01 * vx);
  EXPECT_NEAR(v.z, expected.z, 0.01 * vx);
  EXPECT_NEAR(w.diagnostics().kinetic() / before, 1.0, 1e-3);
}

}  // namespace
}  // namespace talus
