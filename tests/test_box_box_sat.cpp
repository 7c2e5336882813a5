// The box-box separating-axis test skips square roots for edge axes that cannot win. Against
// the plain test (all 15 normalised overlaps, least one wins, faces win ties), it must pick the
// same axis and depth on random pairs: apart, touching, face on face, edge on edge, parallel.
// A lasting contact keeps its axis for as long as box_box_axis_reserve allows: within that
// motion the full test, warm-started, must give that same axis, and the one-axis test its answer.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "talus/collide/box_box.h"
#include "test_random_poses.h"

namespace talus {
namespace {

using testing::random_rotation;

// The plain test: every axis normalised, same tie rules as box_box_sat (no warm start).
struct Plain {
  bool separated;
  int axis;
  double depth;
  double overlap[15];
};

Plain plain_sat(const OrientedBox& a, const OrientedBox& b) {
  double R[3][3], AbsR[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) R[i][j] = dot(a.axis[i], b.axis[j]), AbsR[i][j] = std::abs(R[i][j]) + 1e-12;
  const Vec3 d = b.centre - a.centre;
  const double t[3] = {dot(d, a.axis[0]), dot(d, a.axis[1]), dot(d, a.axis[2])};
  double overlap[15];
  bool valid[15];
  for (int k = 0; k < 3; ++k) {
    overlap[k] = a.half[k] + b.half[0] * AbsR[k][0] + b.half[1] * AbsR[k][1] + b.half[2] * AbsR[k][2] - std::abs(t[k]);
    const double tj = t[0] * R[0][k] + t[1] * R[1][k] + t[2] * R[2][k];
    overlap[3 + k] = a.half[0] * AbsR[0][k] + a.half[1] * AbsR[1][k] + a.half[2] * AbsR[2][k] + b.half[k] - std::abs(tj);
    valid[k] = valid[3 + k] = true;
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int k = 6 + 3 * i + j, i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      const double len = std::sqrt(R[i1][j] * R[i1][j] + R[i2][j] * R[i2][j]);
      valid[k] = len > 1e-6;
      const double ra = a.half[i1] * AbsR[i2][j] + a.half[i2] * AbsR[i1][j];
      const double rb = b.half[j1] * AbsR[i][j2] + b.half[j2] * AbsR[i][j1];
      overlap[k] = (ra + rb - std::abs(t[i2] * R[i1][j] - t[i1] * R[i2][j])) / len;
    }
  Plain r{};
  std::copy(overlap, overlap + 15, r.overlap);
  for (int k = 0; k < 15; ++k)
    if (valid[k] && overlap[k] < 0) {
      r.separated = true, r.axis = k, r.depth = overlap[k];
      return r;
    }
  int best = 0;
  const double margin = 1e-9 * (norm(a.half) + norm(b.half));
  for (int k = 1; k < 15; ++k)
    if (valid[k] && overlap[k] < overlap[best] - (k < 6 ? 0.0 : margin)) best = k;
  r.axis = best, r.depth = overlap[best];
  return r;
}

TEST(BoxBoxSat, AgreesWithThePlainFifteenAxisTest) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  const Quat quarter = Quat::from_axis_angle({0, 0, 1}, std::acos(-1.0) / 2);
  int touching = 0, edge_wins = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const Vec3 ha{13.5e-3, 1e-3, 1.5e-3};  // the arm of the Huet et al. 2021 cross
    const Vec3 hb = trial % 2 ? ha : Vec3{5e-3 * (1.2 + u(rng)), 5e-3 * (1.2 + u(rng)), 5e-3 * (1.2 + u(rng))};
    Quat qa = random_rotation(rng), qb = random_rotation(rng);
    if (trial % 5 == 0) qb = qa;            // parallel: degenerate edge pairs
    if (trial % 5 == 1) qb = qa * quarter;  // crossed arms
    const Pose pa{{0, 0, 0}, qa};
    const Pose pb{{15e-3 * u(rng), 15e-3 * u(rng), 6e-3 * u(rng)}, qb};
    const OrientedBox a = oriented_box(ha, pa), b = oriented_box(hb, pb);
    const Plain want = plain_sat(a, b);
    const BoxBoxSat got = box_box_sat(a, b);
    ASSERT_EQ(got.separated, want.separated) << "trial " << trial;
    if (!got.separated) {
      ++touching;
      if (want.axis >= 6) ++edge_wins;
      // Equal overlaps (parallel faces) may tie to rounding: either axis then.
      if (got.axis != want.axis) ASSERT_NEAR(want.overlap[got.axis], want.depth, 1e-15) << "trial " << trial;
      ASSERT_NEAR(got.depth, want.depth, 1e-15) << "trial " << trial;
    }
  }
  // The sample covers both outcomes of the face/edge competition.
  EXPECT_GT(touching, 2000);
  EXPECT_GT(edge_wins, 50);
}

// Moves a box rigidly so that none of its points moves by more than `travel`, counting a turn by
// theta as 2 R sin(theta / 2) at radius R (PlacedBodies::travel): a random split between a turn
// about a random axis and a random shift.
OrientedBox moved(const Vec3& half, const Pose& pose, double travel, double radius, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> n(0, 1);
  const double turn_share = u(rng);
  const double theta = 2 * std::asin(std::min(1.0, turn_share * travel / (2 * radius)));
  const Vec3 shift = normalized_or_zero(Vec3{n(rng), n(rng), n(rng)}) * ((1 - turn_share) * travel);
  const Quat turn = Quat::from_axis_angle(normalized_or_zero(Vec3{n(rng), n(rng), n(rng)}), theta);
  return oriented_box(half, Pose{pose.position + shift, (turn * pose.orientation).normalized()});
}

TEST(BoxBoxSat, KeptAxisHoldsWhileItsReserveLasts) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> u(-1, 1), share(0, 1);
  const Quat quarter = Quat::from_axis_angle({0, 0, 1}, std::acos(-1.0) / 2);
  const double radius = 13.6e-3;  // bounding radius of the bodies the boxes belong to
  const double turn_per_travel = 0.5 * std::acos(-1.0) / radius;
  int pairs = 0, reusable = 0, checks = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const Vec3 ha{13.5e-3, 1e-3, 1.5e-3};
    const Vec3 hb = trial % 2 ? ha : Vec3{4e-3 * (1.2 + u(rng)), 4e-3 * (1.2 + u(rng)), 4e-3 * (1.2 + u(rng))};
    Quat qa = random_rotation(rng), qb = random_rotation(rng);
    if (trial % 4 == 1) qb = qa * quarter;  // crossed arms
    const Pose pa{{0, 0, 0}, qa};
    const Pose pb{{15e-3 * u(rng), 15e-3 * u(rng), 6e-3 * u(rng)}, qb};
    const BoxBoxSat first = box_box_sat(oriented_box(ha, pa), oriented_box(hb, pb));
    if (first.separated) continue;
    ++pairs;
    const double reserve = box_box_axis_reserve(oriented_box(ha, pa), oriented_box(hb, pb), first.axis, turn_per_travel);
    ASSERT_GE(reserve, 0.0);
    if (reserve > 1e-7) ++reusable;
    // A full query renews the reserve from its own overlaps: the same axis and the same bound.
    for (const int warm : {-1, first.axis}) {
      double fused_reserve = -1;
      const BoxBoxSat fused =
          box_box_sat_with_reserve(oriented_box(ha, pa), oriented_box(hb, pb), warm, turn_per_travel, &fused_reserve);
      ASSERT_EQ(fused.axis, first.axis) << "trial " << trial;
      ASSERT_EQ(fused.depth, first.depth) << "trial " << trial;
      ASSERT_EQ(fused_reserve, reserve) << "trial " << trial << ", warm " << warm;
    }
    for (int k = 0; k < 4; ++k) {
      // Up to the whole reserve, split at random between the two bodies.
      const double travel = reserve * (k == 0 ? 1.0 : share(rng)), to_a = share(rng) * travel;
      const OrientedBox a = moved(ha, pa, to_a, radius, rng), b = moved(hb, pb, travel - to_a, radius, rng);
      const BoxBoxSat full = box_box_sat(a, b, first.axis);
      BoxBoxSat kept;
      ASSERT_TRUE(box_box_sat_on_axis(a, b, first.axis, kept)) << "trial " << trial;
      ASSERT_EQ(full.axis, first.axis) << "trial " << trial << ", reserve " << reserve;
      ASSERT_EQ(kept.separated, full.separated) << "trial " << trial;
      ASSERT_EQ(kept.depth, full.depth) << "trial " << trial;  // to the bit: a restart may reuse or not
      ASSERT_EQ(kept.normal, full.normal) << "trial " << trial;
      ++checks;
    }
  }
  EXPECT_GT(pairs, 2000);
  EXPECT_GT(checks, 8000);
  // The reserve is worth having: most touching pairs may move a tenth of a micrometre or more
  // (a pile's crosses move a few nanometres per step).
  EXPECT_GT(reusable, pairs / 2) << reusable << " of " << pairs;
}

}  // namespace
}  // namespace talus
