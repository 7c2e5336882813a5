// Polyhedra given as mesh files (`mesh = "FILE"`, scenario/mesh_shape_reader.h): a cube as ASCII
// STL, binary STL, OBJ of triangles and OBJ of quads is the box, alone and as a composite's part;
// `mesh_scale` scales the volume by its cube; the shipped icosahedron has its closed-form volume;
// a relative path starts from the scenario's folder and the saved scenario still finds the file;
// open, non-convex and malformed meshes are refused with the scenario's key and the mesh file.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

#include "talus/io/input_error.h"
#include "talus/scenario/scenario.h"
#include "test_mesh_writers.h"

namespace talus {
namespace {

using testing::cube_corners;
using testing::cube_quads;
using testing::fanned;

// One box particle in a large domain, and the species tables given (`species` starts on line 13).
std::string scene(const std::string& species) {
  return R"([run]
end_time = 0.1

[domain]
lo = [-10.0, -10.0, -10.0]
hi = [10.0, 10.0, 10.0]

[species.block]
shape = "box"
density = 700
half_extents = [0.5, 0.5, 0.5]

)" + species + R"(
[contact]
normal_stiffness = 1e4
normal_restitution = 0.5
friction = 0.5

[[particles]]
species = "block"
position = [0.0, 0.0, 0.0]
)";
}

class ScenarioMeshShapes : public testing::MeshFolder {
 protected:
  // The scenario written beside the meshes as case.toml, and read from there.
  Scenario load(const std::string& species) const {
    io::ScenarioFile f = io::ScenarioFile::from_file(write("case.toml", scene(species)));
    return load_scenario(f);
  }
  std::string load_error(const std::string& species) const {
    try {
      load(species);
    } catch (const io::InputError& e) {
      return e.what();
    }
    return "";
  }
  std::string case_toml() const { return (dir_ / "case.toml").string(); }
  void write_cubes(double h) const {
    const std::vector<Vec3> v = cube_corners(h);
    write("cube.stl", testing::ascii_stl_text(v, fanned(cube_quads())));
    write("cube_binary.stl", testing::binary_stl_bytes(v, fanned(cube_quads())));
    write("cube.obj", testing::obj_text(v, fanned(cube_quads())));
    write("cube_quads.obj", testing::obj_text(v, cube_quads()));
  }
};

std::string polyhedron(const std::string& name, const std::string& keys) {
  return "[species." + name + "]\nshape = \"polyhedron\"\ndensity = 700\n" + keys + "\n";
}

void expect_same_body(const nlohmann::json& a, const nlohmann::json& b) {
  EXPECT_NEAR(b["volume"].get<double>(), a["volume"].get<double>(), 1e-12 * a["volume"].get<double>());
  EXPECT_NEAR(b["mass"].get<double>(), a["mass"].get<double>(), 1e-12 * a["mass"].get<double>());
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(b["principal_moments"][k].get<double>(), a["principal_moments"][k].get<double>(),
                1e-12 * a["principal_moments"][k].get<double>());
}

TEST_F(ScenarioMeshShapes, CubeMeshesAreTheBox) {
  write_cubes(0.5);  // corners exact in float32, as binary STL stores them
  const Scenario sc = load(polyhedron("ascii", "mesh = \"cube.stl\"") + polyhedron("binary", "mesh = \"cube_binary.stl\"") +
                           polyhedron("triangles", "mesh = \"cube.obj\"") + polyhedron("quads", "mesh = \"cube_quads.obj\""));
  const nlohmann::json& s = sc.derived["species"];
  EXPECT_NEAR(s["block"]["mass"].get<double>(), 700.0, 1e-12);
  for (const char* name : {"ascii", "binary", "triangles", "quads"}) {
    SCOPED_TRACE(name);
    expect_same_body(s["block"], s[name]);
  }
}

// A composite's part from a mesh, placed off the body's origin: the box still.
TEST_F(ScenarioMeshShapes, ACompositesPartMayBeAMesh) {
  write_cubes(0.5);
  const Scenario sc = load(R"([species.glued]
shape = "composite"
density = 700

[[species.glued.parts]]
shape = "polyhedron"
mesh = "cube.obj"
position = [1.0, 2.0, 3.0]
)");
  expect_same_body(sc.derived["species"]["block"], sc.derived["species"]["glued"]);
  const nlohmann::json& centre = sc.derived["species"]["glued"]["centre_of_mass"];
  EXPECT_NEAR(centre[0].get<double>(), 1.0, 1e-12);
  EXPECT_NEAR(centre[2].get<double>(), 3.0, 1e-12);
}

TEST_F(ScenarioMeshShapes, MeshScaleScalesTheVolumeByItsCube) {
  write_cubes(0.5);
  const Scenario sc = load(polyhedron("metres", "mesh = \"cube.stl\"") +
                           polyhedron("millimetres", "mesh = \"cube.stl\"\nmesh_scale = 1e-3"));
  const nlohmann::json& s = sc.derived["species"];
  EXPECT_NEAR(s["millimetres"]["volume"].get<double>(), 1e-9 * s["metres"]["volume"].get<double>(), 1e-12 * 1e-9);
  EXPECT_NEAR(s["millimetres"]["bounding_radius"].get<double>(), 1e-3 * s["metres"]["bounding_radius"].get<double>(), 1e-15);
  EXPECT_NE(load_error(polyhedron("zero", "mesh = \"cube.stl\"\nmesh_scale = 0")).find("species.zero.mesh_scale: must be positive"),
            std::string::npos);
  // Beside vertices, mesh_scale scales nothing: said so, not silently ignored.
  const std::string unused = load_error(polyhedron(
      "listed", "vertices = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]\nmesh_scale = 1e-3"));
  EXPECT_NE(unused.find("species.listed.mesh_scale: not read: it scales a mesh, and this polyhedron gives vertices"),
            std::string::npos)
      << unused;
}

// A regular icosahedron of circumradius R = 1 mm: edge a = R / sin(2 pi / 5), V = 5/12 (3 + sqrt 5) a^3.
TEST_F(ScenarioMeshShapes, TheExampleIcosahedronHasItsVolume) {
  const std::filesystem::path shapes = std::filesystem::path(TALUS_SOURCE_DIR) / "examples" / "shapes";
  const Scenario sc = load(polyhedron("stl", "mesh = \"" + (shapes / "icosahedron.stl").string() + "\"\nmesh_scale = 1e-3") +
                           polyhedron("obj", "mesh = \"" + (shapes / "icosahedron.obj").string() + "\"\nmesh_scale = 1e-3"));
  const double a = 1e-3 / std::sin(2 * std::numbers::pi / 5);
  const double volume = 5.0 / 12.0 * (3 + std::sqrt(5.0)) * a * a * a;
  for (const char* name : {"stl", "obj"})
    EXPECT_NEAR(sc.derived["species"][name]["volume"].get<double>(), volume, 1e-12 * volume) << name;
}

// The current folder for as long as it lives.
class InFolder {
 public:
  explicit InFolder(const std::filesystem::path& dir) : before_(std::filesystem::current_path()) {
    std::filesystem::current_path(dir);
  }
  ~InFolder() { std::filesystem::current_path(before_); }

 private:
  std::filesystem::path before_;
};

// The scenario's folder is where a relative mesh path starts, not the current folder; the
// scenario as saved (results folder, checkpoint) names the mesh absolutely and loads the same.
TEST_F(ScenarioMeshShapes, RelativePathsStartFromTheScenarioAndSurviveItsCopy) {
  write_cubes(0.5);
  std::filesystem::create_directories(dir_ / "meshes");
  std::filesystem::rename(dir_ / "cube.stl", dir_ / "meshes" / "cube.stl");
  write("case.toml", scene(polyhedron("cube", "mesh = \"meshes/cube.stl\"")));
  std::string saved;
  nlohmann::json cube;
  {
    const InFolder above(dir_.parent_path());  // the scenario as `talus run NAME/case.toml`
    io::ScenarioFile f = io::ScenarioFile::from_file(dir_.filename() / "case.toml");
    cube = load_scenario(f).derived["species"]["cube"];
    saved = f.to_toml();
  }
  EXPECT_NE(saved.find((dir_ / "meshes" / "cube.stl").string()), std::string::npos) << saved;
  io::ScenarioFile copy = io::ScenarioFile::from_string(saved, "results/scenario.toml");
  expect_same_body(cube, load_scenario(copy).derived["species"]["cube"]);
  expect_same_body(load(polyhedron("cube", "mesh = \"cube.obj\"")).derived["species"]["cube"], cube);
}

TEST_F(ScenarioMeshShapes, MeshAndVerticesTogetherAreRefused) {
  write_cubes(0.5);
  const std::string e = load_error(polyhedron("both", "mesh = \"cube.obj\"\nvertices = [[0.0, 0.0, 0.0]]"));
  EXPECT_EQ(e, case_toml() + ":16: species.both.mesh: give either vertices or mesh, not both");
}

// Mesh errors are the key's, at the scenario's line, and go on to name the mesh file.
TEST_F(ScenarioMeshShapes, OpenNonConvexAndMalformedMeshesAreRefusedNamingTheFile) {
  std::vector<std::vector<int>> open = cube_quads();
  open.pop_back();
  write("open.obj", testing::obj_text(cube_corners(0.5), open));
  const std::string hole = load_error(polyhedron("open", "mesh = \"open.obj\""));
  EXPECT_EQ(hole.rfind(case_toml() + ":16: species.open.mesh: " + (dir_ / "open.obj").string() +
                           ": the surface is not closed: edge (",
                       0),
            0u)
      << hole;

  // An L-shaped prism: its inner edge lies on the hull's top and bottom faces, its inner walls inside.
  std::vector<Vec3> l{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
  for (int k = 0; k < 6; ++k) l.push_back(l[k] + Vec3{0, 0, 1});
  std::vector<std::vector<int>> faces{{5, 4, 3, 2, 1, 0}, {6, 7, 8, 9, 10, 11}};
  for (int k = 0; k < 6; ++k) faces.push_back({k, (k + 1) % 6, (k + 1) % 6 + 6, k + 6});
  // The hexagons' fans from corner 0 would cross outside the L: split them at the inner corner.
  faces[0] = {3, 2, 1, 0};
  faces[1] = {9, 10, 11, 6};
  faces.push_back({5, 4, 3, 0});
  faces.push_back({6, 7, 8, 9});
  write("ell.stl", testing::ascii_stl_text(l, fanned(faces)));
  const std::string ell = load_error(polyhedron("ell", "mesh = \"ell.stl\""));
  EXPECT_EQ(ell, case_toml() + ":16: species.ell.mesh: " + (dir_ / "ell.stl").string() +
                     ": the surface is not convex: it encloses 3 where the convex hull of its vertices holds 3.5 "
                     "(triangles cut through the hull between its vertices)")
      << ell;

  write("bad.obj", "# a cube\nv 0 0 0\nv 1 0 0 z\n");
  EXPECT_EQ(load_error(polyhedron("bad", "mesh = \"bad.obj\"")),
            case_toml() + ":16: species.bad.mesh: " + (dir_ / "bad.obj").string() + ":3: v: not a finite number: 'z'");

  write("flat.stl", testing::ascii_stl_text(cube_corners(0.5), {{0, 1, 2}, {0, 2, 1}}));
  EXPECT_EQ(load_error(polyhedron("flat", "mesh = \"flat.stl\"")),
            case_toml() + ":16: species.flat.mesh: " + (dir_ / "flat.stl").string() +
                ": a polyhedron needs at least 4 vertices, the mesh has 3");
  write("empty.stl", "solid nothing\nendsolid nothing\n");
  EXPECT_EQ(load_error(polyhedron("empty", "mesh = \"empty.stl\"")),
            case_toml() + ":16: species.empty.mesh: " + (dir_ / "empty.stl").string() +
                ": no triangles (a polyhedron needs a closed surface)");
  EXPECT_EQ(load_error(polyhedron("absent", "mesh = \"absent.stl\"")),
            case_toml() + ":16: species.absent.mesh: " + (dir_ / "absent.stl").string() +
                ": cannot open: No such file or directory");
}

}  // namespace
}  // namespace talus
