// Mesh files (io/triangle_mesh_file.h) and the closed convex surface check (shape/convex_surface.h):
// one cube read from OBJ, ASCII STL and binary STL, every corner form of OBJ faces, binary STL
// whose header says "solid", malformed files refused at their line, and open or non-convex
// surfaces refused with what is wrong.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <string>

#include "talus/io/input_error.h"
#include "talus/io/triangle_mesh_file.h"
#include "talus/shape/convex_surface.h"
#include "test_mesh_writers.h"

namespace talus {
namespace {

using testing::cube_corners;
using testing::cube_quads;
using testing::fanned;

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const io::InputError& e) {
    return e.what();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

// The mesh's triangles as sets of corner points, for comparing meshes numbered differently.
std::vector<std::array<Vec3, 3>> corner_points(const TriangleMesh& m) {
  std::vector<std::array<Vec3, 3>> out;
  for (const auto& t : m.triangles) out.push_back({m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]});
  return out;
}

class MeshFiles : public testing::MeshFolder {};

TEST_F(MeshFiles, OneCubeFromObjAsciiStlAndBinaryStl) {
  const std::vector<Vec3> v = cube_corners(0.5);
  const TriangleMesh obj = io::read_triangle_mesh(write("cube.obj", testing::obj_text(v, fanned(cube_quads()))));
  const TriangleMesh quads = io::read_triangle_mesh(write("quads.OBJ", testing::obj_text(v, cube_quads())));
  const TriangleMesh ascii = io::read_triangle_mesh(write("cube.stl", testing::ascii_stl_text(v, fanned(cube_quads()))));
  const TriangleMesh binary = io::read_triangle_mesh(write("cube_binary.stl", testing::binary_stl_bytes(v, fanned(cube_quads()))));
  for (const TriangleMesh* m : {&obj, &quads, &ascii, &binary}) {
    EXPECT_EQ(m->vertices.size(), 8u);  // STL's 36 corners welded
    EXPECT_EQ(m->triangles.size(), 12u);
    EXPECT_EQ(corner_points(*m), corner_points(obj));
    EXPECT_NO_THROW(check_closed_convex_surface(*m));
  }
}

TEST_F(MeshFiles, ObjCornerFormsAndBackwardIndices) {
  const std::string plain = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  // The same faces as i/t, i//n, i/t/n and counted back from the last vertex so far, among
  // statements the reader leaves alone; a vertex may have a weight, or a colour.
  const std::string forms = "mtllib cube.mtl\n# a comment\nv 0 0 0\nv 2 0 0 2\nv 0 1 0 0.5 0.5 0.5\nv +0 0 1e0\n"
                            "vt 0 0\nvn 0 0 1\ng all\ns off\nusemtl stone\n"
                            "f 1/1 3/1 2/1\nf 1//1 2//1 4//1   # trailing comment\nf -4/1/1 -1/1/1 -2/1/1\nf\t2 3 -1\n";
  const TriangleMesh a = io::parse_obj_mesh(plain, "plain.obj");
  const TriangleMesh b = io::parse_obj_mesh(forms, "forms.obj");
  EXPECT_EQ(b.vertices, a.vertices);
  EXPECT_EQ(b.triangles, a.triangles);
}

TEST_F(MeshFiles, BinaryStlIsToldBySizeEvenWhenItSaysSolid) {
  const std::vector<Vec3> v = cube_corners(0.25);
  const std::string bytes = testing::binary_stl_bytes(v, fanned(cube_quads()), "solid cube");
  EXPECT_EQ(bytes.size(), 84u + 50u * 12u);
  EXPECT_EQ(io::parse_stl_mesh(bytes, "cube.stl").triangles.size(), 12u);
  // Keywords in capitals, as some exporters write them, and two solids in one file.
  const std::string upper = "SOLID a\nFACET NORMAL 0 0 1\nOUTER LOOP\nVERTEX 0 0 0\nVERTEX 1 0 0\nVERTEX 0 1 0\n"
                            "ENDLOOP\nENDFACET\nENDSOLID a\nsolid b\nendsolid b\n";
  EXPECT_EQ(io::parse_stl_mesh(upper, "upper.stl").triangles.size(), 1u);
  // One byte short: neither binary nor text.
  const std::string e = error_of([&] { io::parse_stl_mesh(bytes.substr(0, bytes.size() - 1), "cut.stl"); });
  EXPECT_EQ(e.rfind("cut.stl: not an STL file: it begins with `solid` but holds NUL bytes", 0), 0u) << e;
  EXPECT_NE(e.find("683 bytes, is not 84 + 50 x the 12 triangles its header counts"), std::string::npos) << e;
}

TEST_F(MeshFiles, MalformedLinesNameFileAndLine) {
  const std::string tetra = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  auto obj_error = [](const std::string& text) { return error_of([&] { io::parse_obj_mesh(text, "m.obj"); }); };
  EXPECT_EQ(obj_error("v 0 0 0\nv 1 0\n"), "m.obj:2: v: expected `v x y z`, got 2 numbers");
  EXPECT_EQ(obj_error("v 0 0 0\n\nv 1 0 zero\n"), "m.obj:3: v: not a finite number: 'zero'");
  EXPECT_EQ(obj_error("v 0 0 nan\n"), "m.obj:1: v: not a finite number: 'nan'");
  EXPECT_EQ(obj_error(tetra + "f 1 2 9\n"), "m.obj:9: f: vertex 9 does not exist (4 vertices)");
  EXPECT_EQ(obj_error(tetra + "f 1 2 -5\n"), "m.obj:9: f: vertex -5 does not exist (4 vertices so far)");
  EXPECT_EQ(obj_error(tetra + "f 1 0 2\n"), "m.obj:9: f: '0' is not a vertex (a whole number from 1, or from -1 backwards)");
  EXPECT_EQ(obj_error(tetra + "f 1 2\n"), "m.obj:9: f: a face needs at least three vertices");
  EXPECT_EQ(obj_error("cstype bspline\n"),
            "m.obj:1: cstype: free-form curves and surfaces are not read; export the surface as triangles or polygons");
  EXPECT_EQ(obj_error("vertex 0 0 0\n"), "m.obj:1: unknown statement 'vertex' (a mesh is read from its v and f lines)");

  auto stl_error = [](const std::string& text) { return error_of([&] { io::parse_stl_mesh(text, "m.stl"); }); };
  const std::string facet = "facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 1 0\n endloop\nendfacet\n";
  EXPECT_EQ(stl_error("solid x\n" + facet + "endsolid x\n"), "");
  EXPECT_EQ(stl_error("solid x\nfacet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 O\n"),
            "m.stl:5: expected a finite number, got 'O'");
  EXPECT_EQ(stl_error("solid x\n" + facet + facet.substr(0, 60)), "m.stl:12: expected `vertex`, got the end of the file");
  EXPECT_EQ(stl_error("solid x\n" + facet), "m.stl:8: expected `facet` or `endsolid`, got the end of the file");
  EXPECT_EQ(stl_error("solid x\n" + facet + "endsolid\nrubbish\n"), "m.stl:10: expected `solid`, got 'rubbish'");
  EXPECT_EQ(stl_error("not a mesh"),
            "m.stl: not an STL file: it does not begin with `solid` (ASCII STL), and its 10 bytes are too few for "
            "binary STL's 84-byte header");
}

TEST_F(MeshFiles, FilesOfOtherFormatsOrMissingAreRefused) {
  const std::string other = error_of([&] { io::read_triangle_mesh(write("cube.ply", "ply\n")); });
  EXPECT_EQ(other, (dir_ / "cube.ply").string() + ": unknown mesh format: expected a Wavefront .obj or an .stl file");
  const std::string missing = error_of([&] { io::read_triangle_mesh(dir_ / "absent.stl"); });
  EXPECT_EQ(missing, (dir_ / "absent.stl").string() + ": cannot open: No such file or directory");
}

// A corner merged with a neighbour within 1e-9 of the mesh's size, as rounding leaves it.
TEST_F(MeshFiles, NearlyEqualCornersAreWelded) {
  const std::string text = "solid x\n"
                           "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"
                           "facet normal 0 0 1\nouter loop\nvertex 1.0000000000001 0 0\nvertex 1 1 0\nvertex 0 1 0\n"
                           "endloop\nendfacet\nendsolid\n";
  const TriangleMesh m = welded(io::parse_stl_mesh(text, "two.stl"));
  EXPECT_EQ(m.vertices.size(), 4u);
  EXPECT_EQ(m.triangles[1][0], m.triangles[0][1]);
  // Far enough apart to be two points: kept apart.
  std::string apart = text;
  apart.replace(apart.find("1.0000000000001"), 15, "1.00001");
  EXPECT_EQ(welded(io::parse_stl_mesh(apart, "two.stl")).vertices.size(), 5u);
}

TriangleMesh mesh_of(const std::vector<Vec3>& v, const std::vector<std::vector<int>>& faces) {
  TriangleMesh m{v, {}};
  for (const auto& t : fanned(faces)) m.triangles.push_back({t[0], t[1], t[2]});
  return m;
}

std::string surface_error(const TriangleMesh& m) { return error_of([&] { check_closed_convex_surface(m); }); }

TEST(ConvexSurface, OpenOrMisorientedSurfacesAreNotClosed) {
  std::vector<std::vector<int>> quads = cube_quads();
  EXPECT_EQ(surface_error(mesh_of(cube_corners(1), quads)), "");
  // Turned inside out as a whole, it is still the cube.
  std::vector<std::vector<int>> inward = quads;
  for (auto& q : inward) std::reverse(q.begin(), q.end());
  EXPECT_EQ(surface_error(mesh_of(cube_corners(1), inward)), "");
  std::vector<std::vector<int>> open(quads.begin(), quads.end() - 1);  // no face at x = +1
  const std::string hole = surface_error(mesh_of(cube_corners(1), open));
  EXPECT_EQ(hole.rfind("the surface is not closed: edge (", 0), 0u) << hole;
  EXPECT_NE(hole.find("belongs to 1 triangle only"), std::string::npos) << hole;
  std::vector<std::vector<int>> flipped = quads;
  std::reverse(flipped[1].begin(), flipped[1].end());  // the top face faces inward
  const std::string turned = surface_error(mesh_of(cube_corners(1), flipped));
  EXPECT_NE(turned.find("is run along in the same direction by 2 triangles"), std::string::npos) << turned;
}

// The top face pushed in at its centre: a vertex inside the hull of the others.
TEST(ConvexSurface, ADentedCubeIsNotConvex) {
  std::vector<Vec3> v = cube_corners(1);
  v.push_back({0, 0, 0.5});
  std::vector<std::vector<int>> faces = cube_quads();
  faces[1] = {4, 5, 8};
  for (const std::vector<int>& t : {std::vector<int>{5, 6, 8}, {6, 7, 8}, {7, 4, 8}}) faces.push_back(t);
  EXPECT_EQ(surface_error(mesh_of(v, faces)),
            "the surface is not convex: vertex (0 0 0.5) lies 0.5 inside the convex hull of the vertices");
  // Pushed in by less than the skin, 1e-6 of the size (3.5e-6): flat, as rounding leaves a face.
  v[8].z = 1 - 1e-7;
  EXPECT_EQ(surface_error(mesh_of(v, faces)), "");
  v[8].z = 1 - 1e-5;
  EXPECT_EQ(surface_error(mesh_of(v, faces)),
            "the surface is not convex: vertex (0 0 0.99999) lies 1e-05 inside the convex hull of the vertices");
}

// Schoenhardt's twisted prism: every corner on the hull, the side quads split along their
// reflex diagonals, so the triangles cut through the hull. Split along the others, it is the hull.
TEST(ConvexSurface, SchoenhardtsPrismIsNotConvex) {
  std::vector<Vec3> v;
  for (int i = 0; i < 3; ++i) v.push_back({std::cos(i * 2 * std::numbers::pi / 3), std::sin(i * 2 * std::numbers::pi / 3), 0});
  for (int i = 0; i < 3; ++i)
    v.push_back({std::cos(i * 2 * std::numbers::pi / 3 + std::numbers::pi / 6),
                 std::sin(i * 2 * std::numbers::pi / 3 + std::numbers::pi / 6), 1});
  std::vector<std::vector<int>> reflex{{0, 2, 1}, {3, 4, 5}}, convex = reflex;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    reflex.insert(reflex.end(), {{i, j, 3 + j}, {i, 3 + j, 3 + i}});
    convex.insert(convex.end(), {{i, j, 3 + i}, {j, 3 + j, 3 + i}});
  }
  EXPECT_EQ(surface_error(mesh_of(v, convex)), "");
  EXPECT_EQ(surface_error(mesh_of(v, reflex)),
            "the surface is not convex: it encloses 0.866 where the convex hull of its vertices holds 1.62 "
            "(triangles cut through the hull between its vertices)");
}

}  // namespace
}  // namespace talus
