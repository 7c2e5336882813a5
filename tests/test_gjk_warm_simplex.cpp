// GJK started from last step's simplex of two box cores (box_simplex.h): the same overlap and
// normal as a start from last step's normal, in fewer iterations; a code made for other boxes
// still gives the right answer; cores that overlap still go to EPA.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "talus/collide/box_simplex.h"
#include "talus/collide/convex_contact.h"
#include "talus/collide/oriented_box.h"
#include "talus/shape/convex_shape.h"

namespace talus {
namespace {

// A cross's arm (Huet et al. 2021, Sec. III B: 27 x 2 x 3 mm) with a 0.1 mm crust.
ConvexShape arm() { return make_box({0.0135, 0.001, 0.0015}, 1e-4); }

Quat random_turn(std::mt19937_64& rng, double largest) {
  std::normal_distribution<double> n(0, 1);
  std::uniform_real_distribution<double> u(-largest, largest);
  return Quat::from_axis_angle(normalized_or_zero(Vec3{n(rng), n(rng), n(rng)}), u(rng));
}

// Two arms touching through their crusts in one of the ways crosses rest on each other: face on
// face (nearly parallel), edge across face, or crossed at right angles.
struct PosedPair {
  Pose a, b;
};
PosedPair touching_pair(std::mt19937_64& rng, int kind) {
  std::uniform_real_distribution<double> u(-1, 1);
  Quat turn_b = random_turn(rng, 0.005);
  if (kind == 1) turn_b = Quat::from_axis_angle({1, 0, 0}, 0.4) * turn_b;        // edge on face
  if (kind == 2) turn_b = Quat::from_axis_angle({0, 0, 1}, 1.5707963) * turn_b;  // crossed
  const Pose a{{}, random_turn(rng, 0.005)};
  // B's centre below A's reach plus its own by 10-50 um (the crusts round off their edges).
  const Vec3 half{0.0135, 0.001, 0.0015};
  auto reach = [&](const Quat& q) {
    return half.x * std::abs(q.rotate({1, 0, 0}).z) + half.y * std::abs(q.rotate({0, 1, 0}).z) +
           half.z * std::abs(q.rotate({0, 0, 1}).z);
  };
  const double height = reach(a.orientation) + reach(turn_b) - 3e-5 + 2e-5 * u(rng);
  return {a, Pose{{0.004 * u(rng), 0.0008 * u(rng), height}, turn_b}};
}

// One step of motion: micrometres and milliradians, as at dt = 2.5e-6 s in a settling pile.
Pose stepped(std::mt19937_64& rng, const Pose& p) {
  std::uniform_real_distribution<double> u(-1, 1);
  return {p.position + Vec3{u(rng), u(rng), u(rng)} * 2e-6, random_turn(rng, 2e-4) * p.orientation};
}

TEST(GjkWarmSimplex, SameOverlapAndNormalInFewerIterations) {
  const ConvexShape box = arm();
  std::mt19937_64 rng(7);
  int cold_iterations = 0, warm_iterations = 0, queries = 0, touching = 0;
  for (int k = 0; k < 3000; ++k) {
    PosedPair p = touching_pair(rng, k % 3);
    ContactCache cold, warm;
    warm.keep_simplex = true;
    crust_contact(box, p.a, box, p.b, &cold);
    crust_contact(box, p.a, box, p.b, &warm);
    for (int step = 0; step < 5; ++step) {
      p.a = stepped(rng, p.a);
      p.b = stepped(rng, p.b);
      ContactCache from_normal{cold.separation, -1, 0};
      const PartContact c = crust_contact(box, p.a, box, p.b, &from_normal);
      const PartContact w = crust_contact(box, p.a, box, p.b, &warm);
      cold = from_normal;
      // Touching: GJK's distance tolerance is 1e-10 of the pair's size (3 cm), 3 pm. Apart, each
      // start stops at its own lower bound on the distance (the pair's sleep), past the crusts.
      ASSERT_EQ(w.delta_n > 0, c.delta_n > 0) << k;
      if (c.delta_n > 0) {
        ASSERT_NEAR(w.delta_n, c.delta_n, 1e-11) << k;
        ASSERT_GT(dot(w.normal, c.normal), 1 - 1e-9) << k;
        ++touching;
      }
      cold_iterations += c.iterations;
      warm_iterations += w.iterations;
      ++queries;
    }
  }
  const double cold_mean = double(cold_iterations) / queries, warm_mean = double(warm_iterations) / queries;
  std::printf("GJK iterations per query between arms: from the normal %.2f, from the simplex %.2f\n", cold_mean,
              warm_mean);
  EXPECT_LT(warm_mean, 0.6 * cold_mean);
  EXPECT_GT(touching, queries / 3);  // the comparison above is mostly of contacts
}

// The boxes' cores as the world holds them (PlacedPart::box with the core's half extents).
OrientedBox core_of(const ConvexShape& box, const Pose& pose) {
  return oriented_box(std::get<Box>(box.core).half_extents, pose);
}

TEST(GjkWarmSimplex, PlacedCoresGiveTheAnswerOfPosedShapes) {
  // crust_box_box_contact reads the boxes' world axes instead of turning every support query by
  // a quaternion: the same contact to GJK's tolerance (1e-10 of 3 cm), cold and warm, touching,
  // apart and with cores pressed into each other (EPA).
  const ConvexShape box = arm();
  const double scale = 2 * box.bounding_radius;
  std::mt19937_64 rng(13);
  int touching = 0, epa = 0;
  for (int k = 0; k < 3000; ++k) {
    PosedPair p = touching_pair(rng, k % 3);
    if (k % 10 == 9) p.b.position.z -= 2.5e-4;  // cores 0.05 mm or more into each other
    ContactCache posed_cache, placed_cache;
    posed_cache.keep_simplex = placed_cache.keep_simplex = k % 2 == 0;
    for (int step = 0; step < 4; ++step) {
      const PartContact c = crust_contact(box, p.a, box, p.b, &posed_cache);
      const PartContact w =
          crust_box_box_contact(core_of(box, p.a), box.crust, core_of(box, p.b), box.crust, scale, &placed_cache);
      ASSERT_EQ(w.method, c.method) << k;
      ASSERT_EQ(w.delta_n > 0, c.delta_n > 0) << k;
      if (c.delta_n > 0) {
        ASSERT_NEAR(w.delta_n, c.delta_n, 1e-11) << k;
        ASSERT_GT(dot(w.normal, c.normal), 1 - 1e-9) << k;
        // The arms meet face on face or edge on face: a patch or a segment of closest points,
        // of which GJK's rounding picks one (as warm and cold starts do). Whichever, GJK's
        // deepest points lie the overlap apart along the normal.
        if (w.method == ContactMethod::kCrustGjk)
          ASSERT_LT(norm(w.point_b - w.point_a - w.normal * w.delta_n), 1e-10) << k;
        ++touching;
        epa += c.method == ContactMethod::kCrustEpa;
      }
      p.a = stepped(rng, p.a);
      p.b = stepped(rng, p.b);
    }
  }
  EXPECT_GT(touching, 3000);
  EXPECT_GT(epa, 300);
}

TEST(GjkWarmSimplex, ACodeOfOtherBoxesStillGivesTheAnswer) {
  // Any code names corners of these boxes: a poor start, never a wrong answer.
  const ConvexShape box = arm();
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<std::uint32_t> bits(0, (1u << 27) - 1);
  for (int k = 0; k < 2000; ++k) {
    const PosedPair p = touching_pair(rng, k % 3);
    ContactCache fresh, stale;
    stale.simplex = (bits(rng) & ~7u) | static_cast<std::uint32_t>(1 + k % 4);
    const PartContact c = crust_contact(box, p.a, box, p.b, &fresh);
    const PartContact s = crust_contact(box, p.a, box, p.b, &stale);
    ASSERT_EQ(s.delta_n > 0, c.delta_n > 0) << k;
    if (c.delta_n > 0) ASSERT_NEAR(s.delta_n, c.delta_n, 1e-11) << k;
  }
}

TEST(GjkWarmSimplex, CoresThatOverlapStillGoToEpa) {
  // Pressed together past both crusts, from a simplex of the last step when they were not.
  const ConvexShape box = arm();
  const Pose a{};
  ContactCache warm;
  warm.keep_simplex = true;
  crust_contact(box, a, box, Pose{{0.001, 0, 3.1e-3}, Quat::from_axis_angle({0, 0, 1}, 0.3)}, &warm);
  // 3 mm thick arms 2.75 mm apart: 0.25 mm of overlap, the cores (crusts 0.1 mm) 0.05 mm into each other.
  const Pose pressed{{0.001, 0, 2.75e-3}, Quat::from_axis_angle({0, 0, 1}, 0.3)};
  ContactCache cold;
  const PartContact c = crust_contact(box, a, box, pressed, &cold);
  const PartContact w = crust_contact(box, a, box, pressed, &warm);
  EXPECT_EQ(w.method, ContactMethod::kCrustEpa);
  EXPECT_EQ(cold.simplex, 0u);  // not asked for: its code is not worked out
  EXPECT_NEAR(w.delta_n, 3e-3 - 2.75e-3, 1e-9);
  EXPECT_NEAR(w.delta_n, c.delta_n, 1e-9);
}

}  // namespace
}  // namespace talus
