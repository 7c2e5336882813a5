// Runout and height measured on top-view images of piles whose answer is known on paper.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "talus/analysis/collapse_height.h"
#include "talus/analysis/collapse_image.h"
#include "talus/analysis/collapse_runout.h"

namespace talus::collapse {
namespace {

constexpr double kPixel = 0.43e-3;  // m, Huet et al. 2021, Sec. III C

// A block of nx * ny * nz cubes of side `side` filling [0, nx side] x [0, ny side] x [0, nz side].
Snapshot block_of_cubes(int nx, int ny, int nz, double side) {
  Snapshot s;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k) {
        ParticleRecord p;
        p.id = static_cast<std::uint32_t>(s.particles.size());
        p.mass = 1;
        p.radius = side * std::sqrt(3.0) / 2;
        p.position = {(i + 0.5) * side, (j + 0.5) * side, (k + 0.5) * side};
        // A quarter turn about z leaves a cube unchanged, and exercises the rotation path.
        p.orientation = Quat::from_axis_angle({0, 0, 1}, std::numbers::pi / 2 * (i % 2));
        s.particles.push_back(p);
      }
  return s;
}

Footprint cube_template(double side) {
  Footprint f;
  f.boxes.push_back({{}, {side / 2, side / 2, side / 2}, Quat{}});
  return f;
}

TEST(CollapseRunout, BlockOfBoxesGivesItsLengthAtEveryThreshold) {
  const double side = 0.01;  // m
  const Snapshot s = block_of_cubes(10, 5, 20, side);  // 0.10 x 0.05 x 0.20 m
  const auto footprints = place_footprints(s, {cube_template(side)});
  const ProjectionImage top = rasterise(footprints, View::Top, {0.0, 0.3, 0.0, 0.05, kPixel});
  const Runout r = measure_runout(top);
  EXPECT_NEAR(r.nominal, 0.10, kPixel);
  EXPECT_NEAR(r.low, 0.10, kPixel);
  EXPECT_NEAR(r.high, 0.10, kPixel);
  EXPECT_FALSE(r.reached_frame_end);
  ASSERT_EQ(r.profile.x.size(), r.profile.intensity.size());
  EXPECT_DOUBLE_EQ(r.profile.intensity.front(), 1.0);
  EXPECT_DOUBLE_EQ(r.profile.intensity.back(), 0.0);
}

TEST(CollapseRunout, EmptyStripBeforeTheWallIsSkipped) {
  const double side = 0.01;
  const Snapshot s = block_of_cubes(10, 5, 20, side);
  const auto footprints = place_footprints(s, {cube_template(side)});
  const ProjectionImage top = rasterise(footprints, View::Top, {-0.02, 0.3, 0.0, 0.05, kPixel});
  EXPECT_NEAR(measure_runout(top).nominal, 0.10, kPixel);
  const ProjectionImage nothing = rasterise({}, View::Top, {0.0, 0.3, 0.0, 0.05, kPixel});
  EXPECT_DOUBLE_EQ(measure_runout(nothing).nominal, 0.0);
}

TEST(CollapseHeight, BlockOfBoxesHasItsHeightWithZeroSpread) {
  const double side = 0.01;
  const Snapshot s = block_of_cubes(10, 5, 20, side);
  const auto footprints = place_footprints(s, {cube_template(side)});
  const ProjectionImage top = rasterise(footprints, View::Top, {0.0, 0.3, 0.0, 0.05, kPixel});
  const HeightProfile h = height_along_width(top, 0.0, side);
  ASSERT_FALSE(h.h.empty());
  EXPECT_NEAR(h.mean, 0.20, 1e-12);
  EXPECT_NEAR(h.q1, 0.20, 1e-12);
  EXPECT_NEAR(h.q3, 0.20, 1e-12);
  EXPECT_DOUBLE_EQ(h.q3 - h.q1, 0.0);
}

// A pile whose plan view is the triangle x / Lw + y / W <= 1, made of one box rotated about z
// with a face on the hypotenuse (the image frame cuts off the rest): the column intensity is
// 1 - x / Lw, so a threshold f is crossed at x = (1 - f) Lw.
TEST(CollapseRunout, WedgeCrossesThresholdsWhereTheGeometrySays) {
  const double Lw = 0.10, W = 0.20, big = 1.0;
  const double len = std::hypot(Lw, W);
  const Vec3 n{W / len, Lw / len, 0};        // outward normal of the hypotenuse
  const double c = Lw * W / len;             // its distance from the origin
  Footprint f;
  f.boxes.push_back({n * (c - big), {big, big, 0.01}, Quat::from_axis_angle({0, 0, 1}, std::atan2(n.y, n.x))});
  const ProjectionImage top = rasterise({f}, View::Top, {0.0, 0.3, 0.0, W, kPixel});
  const Runout r = measure_runout(top);
  // One pixel for the column, plus the x span of one pixel row of the triangle's edge.
  const double tol = kPixel + Lw / top.nv;
  EXPECT_NEAR(r.nominal, 0.90 * Lw, tol);
  EXPECT_NEAR(r.low, 0.80 * Lw, tol);
  EXPECT_NEAR(r.high, 0.99 * Lw, tol);
  // The profile itself follows 1 - x / Lw.
  for (std::size_t a = 0; a < r.profile.x.size(); a += 20) {
    const double expected = std::max(0.0, 1.0 - r.profile.x[a] / Lw);
    EXPECT_NEAR(r.profile.intensity[a], expected, 1.5 / top.nv) << "x = " << r.profile.x[a];
  }
}

// A side-profile wedge z <= H (1 - x / Lw): the height read on a narrow band is the slope's.
TEST(CollapseHeight, SlopedPileReadsTheSurfaceHeightOfTheBand) {
  const double Lw = 0.2, H = 0.1, W = 0.04, big = 1.0;
  const double len = std::hypot(H, Lw);
  const Vec3 n{H / len, 0, Lw / len};
  const double c = Lw * H / len;
  Footprint f;
  // Rotating about -y by the slope angle turns the box's +x axis to n.
  f.boxes.push_back({n * (c - big), {big, big, big}, Quat::from_axis_angle({0, -1, 0}, std::atan2(n.z, n.x))});
  const ProjectionImage top = rasterise({f}, View::Top, {0.0, 0.3, 0.0, W, kPixel});
  const double x = 0.05;
  const HeightProfile h = height_along_width(top, x, x + 5 * kPixel);
  // The band's highest column is its first one, whose centre lies within a pixel of x.
  EXPECT_NEAR(h.mean, H * (1 - x / Lw), H / Lw * kPixel);
  EXPECT_NEAR(h.q3 - h.q1, 0.0, 1e-12);
  // The side view of the same pile is occupied below the slope only.
  const ProjectionImage side = rasterise({f}, View::Side, {0.0, 0.3, 0.0, 0.15, kPixel});
  const int a = static_cast<int>(x / kPixel);
  const double surface = H * (1 - side.u_centre(a) / Lw);
  EXPECT_TRUE(side.occupied(a, static_cast<int>(0.9 * surface / kPixel)));
  EXPECT_FALSE(side.occupied(a, static_cast<int>(1.1 * surface / kPixel)));
}

TEST(CollapseHeight, QuantilesInterpolateLikeNumpy) {
  EXPECT_DOUBLE_EQ(quantile({1, 2, 3, 4}, 0.25), 1.75);
  EXPECT_DOUBLE_EQ(quantile({4, 1, 3, 2}, 0.75), 3.25);
  EXPECT_DOUBLE_EQ(quantile({5}, 0.25), 5.0);
}

TEST(CollapseImage, SpheresFillTheirDiscAndReportTheirTop) {
  Footprint f;
  f.spheres.push_back({{0.02, 0.02, 0.01}, 0.01});
  const ProjectionImage top = rasterise({f}, View::Top, {0.0, 0.04, 0.0, 0.04, kPixel});
  int filled = 0;
  double highest = 0;
  for (int a = 0; a < top.nu; ++a)
    for (int b = 0; b < top.nv; ++b)
      if (top.occupied(a, b)) {
        ++filled;
        highest = std::max(highest, top.top[top.index(a, b)]);
      }
  const double disc = std::numbers::pi * 0.01 * 0.01 / (kPixel * kPixel);
  EXPECT_NEAR(filled, disc, 0.03 * disc);
  EXPECT_NEAR(highest, 0.02, 1e-5);
}

}  // namespace
}  // namespace talus::collapse
