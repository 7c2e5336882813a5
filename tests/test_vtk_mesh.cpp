// ParaView output without VTK: shape triangulations are closed, outward and of the right
// volume; plane clipping; the .pvd collection text; the .vtu layout's own checks.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <unistd.h>
#include <utility>

#include "talus/io/vtk_pvd.h"
#include "talus/io/vtk_shape_mesh.h"
#include "talus/io/vtk_walls.h"
#include "talus/io/vtk_xml.h"

namespace talus::io {
namespace {

// Closed and consistently oriented: every directed edge appears once and its reverse once.
void expect_closed(const SurfaceMesh& m) {
  std::map<std::pair<int, int>, int> edges;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++edges[{t[k], t[(k + 1) % 3]}];
  for (const auto& [e, count] : edges) {
    EXPECT_EQ(count, 1) << e.first << "->" << e.second;
    EXPECT_EQ(edges.count({e.second, e.first}), 1u) << e.first << "->" << e.second;
  }
}

// Divergence theorem: positive only when the triangles face outwards.
double volume(const SurfaceMesh& m) {
  double v = 0;
  for (const auto& t : m.triangles)
    v += dot(m.vertices[t[0]], cross(m.vertices[t[1]], m.vertices[t[2]])) / 6;
  return v;
}

TEST(VtkMesh, BoxIsTwelveOutwardTriangles) {
  const SurfaceMesh m = triangulate(make_box({1, 2, 3}).geometry);
  EXPECT_EQ(m.vertices.size(), 8u);
  EXPECT_EQ(m.triangles.size(), 12u);
  expect_closed(m);
  EXPECT_NEAR(volume(m), 48, 1e-12);
}

TEST(VtkMesh, CylinderIsSixteenSidedPrism) {
  const SurfaceMesh m = triangulate(make_cylinder(0.5, 2).geometry);
  EXPECT_EQ(m.triangles.size(), 60u);  // 32 side + 2 x 14 cap
  expect_closed(m);
  const double prism = 0.5 * 16 * 0.25 * std::sin(2 * std::numbers::pi / 16) * 4;
  EXPECT_NEAR(volume(m), prism, 1e-12);
}

TEST(VtkMesh, PolyhedronUsesItsFaces) {
  const SurfaceMesh m = triangulate(make_polyhedron({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, -1, -1}}).geometry);
  EXPECT_EQ(m.triangles.size(), 4u);
  expect_closed(m);
  EXPECT_NEAR(volume(m), 4.0 / 6.0, 1e-12);  // |det| / 6 of the edge vectors from (-1,-1,-1)
}

TEST(VtkMesh, SphereIsClosedAndCloseToTheBall) {
  const SurfaceMesh m = triangulate(make_sphere(1).geometry);
  expect_closed(m);
  const double ball = 4 * std::numbers::pi / 3;  // an inscribed 8 x 16 UV sphere holds 94 % of it
  EXPECT_GT(volume(m), 0.9 * ball);
  EXPECT_LT(volume(m), ball);
}

TEST(VtkMesh, HuetCrossIsTwoBoxesWithPartIndex) {
  const CompositeShape cross = make_huet_cross();
  EXPECT_FALSE(is_plain_sphere(cross));
  CompositeShape sphere;
  sphere.add(make_sphere(1e-3), Pose{});
  EXPECT_TRUE(is_plain_sphere(sphere));
  const SurfaceMesh m = triangulate(cross);
  ASSERT_EQ(m.triangles.size(), 24u);
  EXPECT_EQ(m.part[0], 0);
  EXPECT_EQ(m.part[23], 1);
  double lo = 0, hi = 0;
  for (const Vec3& v : m.vertices) lo = std::min(lo, v.y), hi = std::max(hi, v.y);
  EXPECT_NEAR(hi - lo, 27e-3, 1e-15);  // the second arm, turned onto y
}

TEST(VtkMesh, PlaneClippedToBox) {
  const Aabb box{{0, 0, 0}, {1, 2, 3}};
  const auto floor = clip_plane_to_box({0, 0, 0}, {0, 0, 1}, box);  // along the bottom face
  ASSERT_EQ(floor.size(), 4u);
  for (const Vec3& p : floor) EXPECT_EQ(p.z, 0);
  // Counter-clockwise about the normal.
  EXPECT_GT(dot(cross(floor[1] - floor[0], floor[2] - floor[0]), Vec3{0, 0, 1}), 0);
  EXPECT_EQ(clip_plane_to_box({0, 0, 1.5}, {0, 0, -1}, box).size(), 4u);
  const Aabb cube{{0, 0, 0}, {1, 1, 1}};
  EXPECT_EQ(clip_plane_to_box({0.5, 0.5, 0.5}, {1, 1, 1}, cube).size(), 6u);  // through the centre
  EXPECT_EQ(clip_plane_to_box({1, 0, 0}, {1, 1, 1}, cube).size(), 3u);        // through 3 corners
  EXPECT_EQ(clip_plane_to_box({0.1, 0, 0}, {1, 1, 1}, box).size(), 3u);    // cuts a corner off
  EXPECT_TRUE(clip_plane_to_box({0, 0, 5}, {0, 0, 1}, box).empty());       // misses the box
}

TEST(VtkMesh, PvdListsFramesRelativeToItsDirectory) {
  const auto dir = std::filesystem::temp_directory_path() / ("talus_vtk_pvd_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  PvdSeries series(dir / "particles.pvd");
  series.add(0, "particles_000000.vtu");
  series.add(0.1, dir / "particles_000001.vtu");
  EXPECT_EQ(series.entries()[1].file, "particles_000001.vtu");
  const std::string text = series.xml();
  EXPECT_NE(text.find("timestep=\"0.1\" group=\"\" part=\"0\" file=\"particles_000001.vtu\""), std::string::npos)
      << text;
  EXPECT_TRUE(std::filesystem::exists(dir / "particles.pvd"));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator{}), 1);
  std::filesystem::remove_all(dir);
}

TEST(VtkMesh, GridRejectsBadCellsAndArrays) {
  VtuGrid grid;
  grid.add_point({0, 0, 0});
  EXPECT_THROW(grid.add_cell(VtkCellType::kLine, {0, 1}), std::out_of_range);
  grid.add_cell(VtkCellType::kVertex, {0});
  const std::vector<double> two = {1, 2};
  grid.add_array(VtuGrid::Where::kPoint, "r", 1, two);
  EXPECT_THROW(grid.serialize(), std::logic_error);
  EXPECT_EQ(xml_escape("a<b&\"c\""), "a&lt;b&amp;&quot;c&quot;");
}

}  // namespace
}  // namespace talus::io
