// The travel bound that lets a pair found apart be skipped: no point of a body may move farther
// than its travel, for any sequence of translations and turns, small or large.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "talus/shape/composite_shape.h"
#include "talus/world/placed_bodies.h"

namespace talus {
namespace {

Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0, 1);
  return normalized_or_zero(Vec3{n(rng), n(rng), n(rng)});
}

TEST(PlacedBodies, TravelBoundsTheDisplacementOfEveryPointOfTheBody) {
  std::vector<CompositeShape> shapes(1);
  shapes.push_back(make_huet_cross());
  const double radius = shapes[1].bounding_radius;
  ParticleStore p;
  p.resize(1);
  p.owned = 1;
  p.shape[0] = 1;
  p.radius[0] = radius;
  p.orientation[0] = Quat{};
  // Sample points: the cross's arm tips and points inside its bounding ball.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Vec3> body_points = {{radius, 0, 0}, {-radius, 0, 0}, {0, radius, 0}, {0, 0, radius}};
  for (int k = 0; k < 200; ++k) body_points.push_back(random_unit(rng) * (radius * std::cbrt(u(rng))));
  const Pose start{p.position[0], p.orientation[0]};

  PlacedBodies placed;
  placed.restart_travel();
  placed.place(p, shapes);
  double tightest = 0;  // largest displacement / travel seen
  for (int step = 0; step < 2000; ++step) {
    // Steps from a micro-turn to a half turn: the chord, not the arc or the angle, must bound it.
    const double angle = (step % 3 == 0 ? 3.1 : 1e-3) * u(rng);
    p.orientation[0] = (Quat::from_axis_angle(random_unit(rng), angle) * p.orientation[0]).normalized();
    p.position[0] += random_unit(rng) * (1e-4 * u(rng));
    placed.place(p, shapes);
    const Pose now{p.position[0], p.orientation[0]};
    double moved = 0;
    for (const Vec3& r : body_points) moved = std::max(moved, norm(now.to_parent(r) - start.to_parent(r)));
    ASSERT_LE(moved, placed.travel(0) * (1 + 1e-12)) << "step " << step;
    if (step == 0) tightest = moved / placed.travel(0);
  }
  // One step of a pure turn plus a move: the bound is reached by some point within the sampling.
  EXPECT_GT(tightest, 0.5);

  // A rebuild restarts the travel.
  placed.restart_travel();
  placed.place(p, shapes);
  EXPECT_EQ(placed.travel(0), 0.0);
}

}  // namespace
}  // namespace talus
