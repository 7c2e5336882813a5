// Refit of a face manifold from its feature ids (box_box_refit, manifold.h): while the clip of
// the incident face keeps the features it was first made from, the points rebuilt from those
// features alone are the clip's (vertices to the bit, intersections to rounding); ids that name
// no such point are refused, so that the caller clips instead.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <vector>

#include "talus/collide/manifold.h"
#include "test_random_poses.h"

namespace talus {
namespace {

using testing::random_rotation;
using testing::random_unit;

const double kPi = std::acos(-1.0);
using testing::kArm;

std::vector<std::uint32_t> ids_of(const ContactManifold& m) {
  std::vector<std::uint32_t> ids;
  for (int k = 0; k < m.count; ++k) ids.push_back(m.points[k].feature_id);
  return ids;
}

// Arm pairs lying face on face (crossed, parallel, or crossed at a random angle and slightly
// tilted, so that the clip makes vertices, edge-plane and corner points), b moved by a random
// walk of 1e-7 m and 1e-5 rad a step. At every step where the clip's features are the first
// clip's, the refit must give its points: the same count, normal and ids, positions and depths
// within 1e-15 m (coordinates of 1e-2 m carry a rounding of 2e-18 m per operation; a clip
// chains at most a dozen).
TEST(ManifoldRefit, GivesTheClipsPointsWhileTheFeaturesLast) {
  std::mt19937_64 rng(2029);
  std::uniform_real_distribution<double> u(-1, 1), share(0, 1);
  long matched = 0, changed = 0, points = 0, exact = 0, kinds[3] = {0, 0, 0};
  for (int trial = 0; trial < 300; ++trial) {
    const Quat qa = random_rotation(rng);
    Quat turn = Quat::from_axis_angle({0, 0, 1}, kPi / 2);
    if (trial % 3 == 1) turn = Quat::from_axis_angle({0, 0, 1}, 0.3 * u(rng));
    if (trial % 3 == 2) turn = (Quat::from_axis_angle({0, 0, 1}, kPi * u(rng)) * Quat::from_axis_angle(random_unit(rng), 0.02)).normalized();
    const Pose pa{{0, 0, 0}, qa};
    Pose pb{qa.rotate({10e-3 * u(rng), 2e-3 * u(rng), 2.99e-3}), (qa * turn).normalized()};  // b lies on a's face
    const OrientedBox a = oriented_box(kArm, pa);
    const BoxBoxSat first = box_box_sat(a, oriented_box(kArm, pb));
    if (first.separated || first.axis >= 6) continue;
    const ContactManifold clipped = box_box_manifold(a, oriented_box(kArm, pb), first);
    if (clipped.count == 0) continue;
    const std::vector<std::uint32_t> stored = ids_of(clipped);
    const Vec3 drift = random_unit(rng), axis = random_unit(rng);
    int sat_axis = first.axis;
    for (int step = 0; step < 40; ++step) {
      pb.position += drift * (1e-7 * share(rng));
      pb.orientation = (Quat::from_axis_angle(axis, 1e-5 * share(rng)) * pb.orientation).normalized();
      const OrientedBox b = oriented_box(kArm, pb);
      const BoxBoxSat sat = box_box_sat(a, b, sat_axis);
      if (sat.separated || sat.axis != first.axis) break;
      sat_axis = sat.axis;
      const ContactManifold clip = box_box_manifold(a, b, sat);
      ContactManifold refit;
      ASSERT_TRUE(box_box_refit(a, b, stored.data(), static_cast<int>(stored.size()), refit)) << "trial " << trial;
      if (ids_of(clip) != stored) {
        ++changed;  // a vertex crossed a side plane or the reference face: the clip's to find
        continue;
      }
      ++matched;
      ASSERT_EQ(refit.count, clip.count) << "trial " << trial << " step " << step;
      ASSERT_EQ(refit.normal, clip.normal);
      for (int k = 0; k < clip.count; ++k) {
        const ManifoldPoint &r = refit.points[k], &c = clip.points[k];
        ASSERT_EQ(r.feature_id, c.feature_id);
        EXPECT_NEAR(r.delta_n, c.delta_n, 1e-15) << "trial " << trial << " step " << step << " point " << k;
        EXPECT_LT(norm(r.point - c.point), 1e-15) << "trial " << trial << " step " << step << " point " << k;
        EXPECT_LT(norm(r.point_a - c.point_a), 1e-15);
        EXPECT_LT(norm(r.point_b - c.point_b), 1e-15);
        const unsigned edges = std::popcount((c.feature_id >> 8) & 0xFFu);
        ++kinds[edges == 2 ? 0 : edges == 1 ? 1 : 2];
        ++points;
        if (edges == 2) EXPECT_EQ(r.point, c.point) << "a vertex is the clip's to the bit";
        exact += r.point == c.point && r.delta_n == c.delta_n;
      }
    }
  }
  std::printf("%ld steps with the first clip's features (%ld points: %ld vertices, %ld edge-plane, %ld corners; "
              "%ld equal to the bit), %ld with other features\n",
              matched, points, kinds[0], kinds[1], kinds[2], exact, changed);
  EXPECT_GT(matched, 1000);
  EXPECT_GT(kinds[0], 500);  // every kind of point was tested many times
  EXPECT_GT(kinds[1], 2000);
  EXPECT_GT(kinds[2], 300);
}

// Ids the clip never makes, or of an edge-edge contact, are refused: the caller clips.
TEST(ManifoldRefit, RefusesIdsThatNameNoFacePoint) {
  const OrientedBox a = oriented_box(kArm, Pose{});
  const OrientedBox b = oriented_box(kArm, Pose{{0, 0, 2.99e-3}, Quat::from_axis_angle({0, 0, 1}, kPi / 2)});
  const BoxBoxSat sat = box_box_sat(a, b);
  ASSERT_LT(sat.axis, 6);
  const ContactManifold m = box_box_manifold(a, b, sat);
  ASSERT_EQ(m.count, 4);
  ContactManifold out;
  std::vector<std::uint32_t> ids = ids_of(m);
  EXPECT_TRUE(box_box_refit(a, b, ids.data(), 4, out));
  EXPECT_EQ(out.count, 4);
  const std::uint32_t faces = ids[0] & 0xFFFF0000u;
  const std::uint32_t bad[] = {
      0xFFu << 24 | 7u,          // an edge-edge contact
      faces | 0b0101u << 8,      // two edges that share no vertex
      faces | 0b0111u << 8,      // three edges
      faces | 0b0011u,           // two opposite side planes
      faces | 0b0001u << 8,      // an edge with no plane
      (ids[0] & 0xFF000000u) | (ids[0] >> 24) << 16 | 0b1001u << 8,  // both faces on one box
  };
  for (std::uint32_t id : bad) {
    std::uint32_t one[] = {id};
    EXPECT_FALSE(box_box_refit(a, b, one, 1, out)) << std::hex << id;
  }
  ids[2] ^= 1u << 16;  // another incident face than the first point's
  EXPECT_FALSE(box_box_refit(a, b, ids.data(), 4, out));
  EXPECT_FALSE(box_box_refit(a, b, ids.data(), 0, out));
}

}  // namespace
}  // namespace talus
