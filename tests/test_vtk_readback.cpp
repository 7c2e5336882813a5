// ParaView output read back by VTK itself: tools/vtk_readback.py (VTK's XML readers, from
// Debian's python3-vtk9) prints what VTK sees as JSON, and the test checks it against the
// snapshot. A missing python3-vtk9 is a failure, not a skip: without it nothing here is checked.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <string>
#include <unistd.h>
#include <sys/wait.h>
#include <vector>

#include <nlohmann/json.hpp>

#include "talus/io/vtk_contacts.h"
#include "talus/io/vtk_output.h"
#include "talus/io/vtk_particles.h"
#include "talus/io/vtk_walls.h"

namespace fs = std::filesystem;
using nlohmann::json;

namespace talus::io {
namespace {

constexpr int kVtkVertex = 1, kVtkLine = 3, kVtkTriangle = 5, kVtkQuad = 9;

// Runs tools/vtk_readback.py on the files; null json (after a test failure) when it fails.
json read_back(const std::vector<fs::path>& files) {
  const std::string python = "/usr/bin/python3";
  if (!fs::exists(python)) {
    ADD_FAILURE() << python << " not found: the VTK readback tests need python3 and python3-vtk9 "
                               "(scripts/install-deps.sh)";
    return nullptr;
  }
  std::string command = python + " " + TALUS_SOURCE_DIR "/tools/vtk_readback.py";
  for (const fs::path& f : files) command += " '" + f.string() + "'";
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) {
    ADD_FAILURE() << "cannot run " << command;
    return nullptr;
  }
  std::string out;
  std::array<char, 4096> buf{};
  while (std::size_t n = std::fread(buf.data(), 1, buf.size(), pipe)) out.append(buf.data(), n);
  const int status = ::pclose(pipe);
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (code == 3) {
    ADD_FAILURE() << "python3-vtk9 is not importable by " << python
                  << ": install it (apt-get install python3-vtk9, or scripts/install-deps.sh)";
    return nullptr;
  }
  if (code != 0) {
    ADD_FAILURE() << "vtk_readback.py failed (exit " << code << ") on: " << command << "\n" << out;
    return nullptr;
  }
  return json::parse(out);
}

std::vector<double> values(const json& array) { return array.at("values").get<std::vector<double>>(); }

class VtkReadback : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("talus_vtk_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);

    CompositeShape sphere;
    sphere.add(make_sphere(1e-3), Pose{});
    shapes_ = {sphere, make_huet_cross()};

    snap_.time = 0.25;
    snap_.domain_min = {0, 0, 0};
    snap_.domain_max = {0.1, 0.1, 0.1};
    for (int k = 0; k < 3; ++k) {
      ParticleRecord p;
      p.id = 10 + k;
      p.species = k % 2;
      p.radius = 1e-3;
      p.position = {0.01 + 0.0019 * k, 0.02, 0.001};
      p.velocity = {0.1 * k, -0.2, 0.3 + k};
      p.angular_velocity = {0, 0, 5.0 * k};
      snap_.particles.push_back(p);
    }
    ParticleRecord cross;  // arms along x and, turned 90 degrees about x, along z
    cross.id = 42;
    cross.shape = 1;
    cross.radius = shapes_[1].bounding_radius;
    cross.fixed = true;
    cross.position = {0.05, 0.05, 0.02};
    cross.orientation = Quat::from_axis_angle({1, 0, 0}, 0.5 * std::numbers::pi);
    snap_.particles.push_back(cross);

    ContactRecord pp;  // between spheres 0 and 1
    pp.i = 0;
    pp.j = 1;
    pp.normal = {-1, 0, 0};
    pp.point = {0.01095, 0.02, 0.001};
    pp.force = {-2.5, 0.5, 0};
    pp.overlap = 1e-4;
    ContactRecord pw;  // sphere 2 on the floor
    pw.i = 2;
    pw.wall = 0;
    pw.normal = {0, 0, 1};
    pw.point = {0.0138, 0.02, 0};
    pw.force = {0, 0, 7.0};
    pw.overlap = 2e-5;
    snap_.contacts = {pp, pw};

    Wall floor;
    floor.name = "floor";
    floor.normal = {0, 0, 1};
    walls_ = {floor};
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path dir_;
  std::vector<CompositeShape> shapes_;
  Snapshot snap_;
  std::vector<Wall> walls_;
};

TEST_F(VtkReadback, ParticlesAreVerticesWithTheirData) {
  write_particles_vtu(dir_ / "particles.vtu", snap_);
  const json r = read_back({dir_ / "particles.vtu"});
  ASSERT_FALSE(r.is_null());
  const json& g = r.at((dir_ / "particles.vtu").string());
  EXPECT_EQ(g["points"], 4);
  EXPECT_EQ(g["cells"], 4);
  for (int type : g["cell_types"]) EXPECT_EQ(type, kVtkVertex);
  const json& pd = g["point_data"];
  EXPECT_EQ(values(pd["id"]), (std::vector<double>{10, 11, 12, 42}));
  EXPECT_EQ(pd["id"]["type"], "unsigned int");
  EXPECT_EQ(pd["velocity"]["components"], 3);
  const std::vector<double> v = values(pd["velocity"]);
  ASSERT_EQ(v.size(), 12u);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(v[3 * k + 0], snap_.particles[k].velocity.x);
    EXPECT_EQ(v[3 * k + 1], snap_.particles[k].velocity.y);
    EXPECT_EQ(v[3 * k + 2], snap_.particles[k].velocity.z);
  }
  EXPECT_EQ(pd["orientation"]["components"], 4);
  EXPECT_EQ(values(pd["orientation"])[12], snap_.particles[3].orientation.w);
  EXPECT_EQ(values(pd["fixed"]), (std::vector<double>{0, 0, 0, 1}));
  EXPECT_EQ(values(pd["species"]), (std::vector<double>{0, 1, 0, 0}));
  EXPECT_EQ(values(pd["angular_velocity"])[8], 10.0);
  EXPECT_EQ(values(pd["radius"])[0], 1e-3);
  EXPECT_DOUBLE_EQ(g["bounds"][0].get<double>(), 0.01);
}

TEST_F(VtkReadback, CrossSurfaceIsTwoBoxesSpanning27mm) {
  write_shapes_vtu(dir_ / "shapes.vtu", snap_, shapes_);
  const json r = read_back({dir_ / "shapes.vtu"});
  ASSERT_FALSE(r.is_null());
  const json& g = r.at((dir_ / "shapes.vtu").string());
  EXPECT_EQ(g["cells"], 24);  // the spheres are glyphs, only the cross is meshed
  EXPECT_EQ(g["points"], 16);
  for (int type : g["cell_types"]) EXPECT_EQ(type, kVtkTriangle);
  const auto b = g["bounds"].get<std::vector<double>>();
  ASSERT_EQ(b.size(), 6u);
  // Arms along x and (after the turn about x) z; the 3 mm thickness now along y.
  EXPECT_NEAR(b[1] - b[0], 27e-3, 1e-12);
  EXPECT_NEAR(b[3] - b[2], 3e-3, 1e-12);
  EXPECT_NEAR(b[5] - b[4], 27e-3, 1e-12);
  EXPECT_NEAR(0.5 * (b[0] + b[1]), 0.05, 1e-12);
  EXPECT_NEAR(0.5 * (b[4] + b[5]), 0.02, 1e-12);
  const json& cd = g["cell_data"];
  for (double id : values(cd["id"])) EXPECT_EQ(id, 42);
  const std::vector<double> part = values(cd["part"]);
  EXPECT_EQ(std::count(part.begin(), part.end(), 1.0), 12);
  EXPECT_EQ(cd["orientation"]["components"], 4);
}

TEST_F(VtkReadback, ContactsAreLinesWithForces) {
  write_contacts_vtu(dir_ / "contacts.vtu", snap_);
  const json r = read_back({dir_ / "contacts.vtu"});
  ASSERT_FALSE(r.is_null());
  const json& g = r.at((dir_ / "contacts.vtu").string());
  EXPECT_EQ(g["cells"], 2);
  EXPECT_EQ(g["points"], 4);
  for (int type : g["cell_types"]) EXPECT_EQ(type, kVtkLine);
  const json& cd = g["cell_data"];
  EXPECT_EQ(values(cd["force"]), (std::vector<double>{-2.5, 0.5, 0, 0, 0, 7}));
  EXPECT_EQ(values(cd["normal_force"]), (std::vector<double>{2.5, 7}));
  EXPECT_EQ(values(cd["tangential_force"]), (std::vector<double>{0.5, 0}));
  EXPECT_EQ(values(cd["overlap"]), (std::vector<double>{1e-4, 2e-5}));
  EXPECT_EQ(values(cd["i"]), (std::vector<double>{10, 12}));  // particle ids
  EXPECT_EQ(values(cd["j"]), (std::vector<double>{11, -1}));
  EXPECT_EQ(values(cd["wall"]), (std::vector<double>{-1, 0}));
  const auto b = g["bounds"].get<std::vector<double>>();  // from sphere 0 to the floor point
  EXPECT_DOUBLE_EQ(b[0], 0.01);
  EXPECT_DOUBLE_EQ(b[1], 0.0138);
  EXPECT_DOUBLE_EQ(b[4], 0);
}

TEST_F(VtkReadback, PeriodicContactDrawnToNearestImage) {
  snap_.periodic[0] = true;
  snap_.particles[1].position.x = 0.0995;  // sphere 1 across the x boundary from sphere 0
  snap_.particles[0].position.x = 0.0005;
  write_contacts_vtu(dir_ / "contacts.vtu", snap_);
  const json r = read_back({dir_ / "contacts.vtu"});
  ASSERT_FALSE(r.is_null());
  const json& g = r.at((dir_ / "contacts.vtu").string());
  EXPECT_EQ(values(g["cell_data"]["periodic"]), (std::vector<double>{1, 0}));
  const auto b = g["bounds"].get<std::vector<double>>();
  EXPECT_NEAR(b[0], -0.0005, 1e-15);  // the image of sphere 1, just outside the box
}

TEST_F(VtkReadback, WallsAreQuads) {
  Wall gate;  // bounded, rising at 1 m/s^2 from t = 0: 31.25 mm up at t = 0.25 s
  gate.origin = {0.03, 0.05, 0.02};
  gate.normal = {-1, 0, 0};
  gate.bounded = true;
  gate.axis_u = {0, 1, 0};
  gate.axis_v = {0, 0, 1};
  gate.half_extent_u = 0.05;
  gate.half_extent_v = 0.02;
  gate.motion.kind = WallMotion::Kind::accelerated;
  gate.motion.acceleration = 1;
  gate.motion.top_speed = 10;
  walls_.push_back(gate);
  write_walls_vtu(dir_ / "walls.vtu", walls_, snap_.time, Aabb{snap_.domain_min, snap_.domain_max});
  const json r = read_back({dir_ / "walls.vtu"});
  ASSERT_FALSE(r.is_null());
  const json& g = r.at((dir_ / "walls.vtu").string());
  EXPECT_EQ(g["cells"], 2);
  EXPECT_EQ(g["cell_types"], json({kVtkQuad, kVtkQuad}));
  const auto b = g["bounds"].get<std::vector<double>>();
  EXPECT_DOUBLE_EQ(b[0], 0);
  EXPECT_DOUBLE_EQ(b[1], 0.1);  // the floor spans the domain
  EXPECT_NEAR(b[5], 0.02 + 0.02 + 0.5 * 0.25 * 0.25, 1e-15);  // top of the risen gate
  EXPECT_EQ(values(g["cell_data"]["wall"]), (std::vector<double>{0, 1}));
  EXPECT_EQ(values(g["cell_data"]["velocity"])[5], 0.25);
}

TEST_F(VtkReadback, OutputWritesSeriesReadableWhileRunning) {
  VtkOutput out(dir_ / "vtk", shapes_);
  out.write_frame(snap_, walls_);
  snap_.time = 0.5;
  snap_.contacts.pop_back();
  out.write_frame(snap_, walls_);
  const fs::path d = dir_ / "vtk";
  for (const char* f : {"particles_000001.vtu", "shapes_000001.vtu", "contacts_000001.vtu", "walls_000001.vtu"})
    EXPECT_TRUE(fs::exists(d / f)) << f;
  const json r = read_back({d / "particles.pvd", d / "shapes.pvd", d / "contacts.pvd", d / "walls.pvd"});
  ASSERT_FALSE(r.is_null());
  const json& contacts = r.at((d / "contacts.pvd").string());
  EXPECT_EQ(contacts["type"], "Collection");
  EXPECT_EQ(contacts["timesteps"], json({0.25, 0.5}));
  EXPECT_EQ(contacts["cells"], json({2, 1}));
  EXPECT_EQ(r.at((d / "shapes.pvd").string())["cells"], json({24, 24}));
  EXPECT_EQ(r.at((d / "particles.pvd").string())["files"], json({"particles_000000.vtu", "particles_000001.vtu"}));
}

// A run of spheres writes no surface frames: a world's shape table always has its shape 0 (no
// parts), and one-sphere composites have no surface beyond the particles' own glyphs.
TEST_F(VtkReadback, SpheresAloneWriteNoShapeSeries) {
  CompositeShape sphere;
  sphere.add(make_sphere(0.01), Pose{});
  VtkOutput out(dir_ / "vtk", {CompositeShape{}, sphere});
  out.write_frame(snap_, walls_);
  EXPECT_TRUE(fs::exists(dir_ / "vtk" / "particles.pvd"));
  EXPECT_FALSE(fs::exists(dir_ / "vtk" / "shapes.pvd"));
  EXPECT_FALSE(fs::exists(dir_ / "vtk" / "shapes_000000.vtu"));
}

// A frame in two pieces, as two ranks write it: rank 0 holds spheres 0 and 2 and the cross,
// rank 1 sphere 1, whose contact with sphere 0 rank 1 lists, with sphere 0 as its partner
// appended to the piece. Joined by the .pvtu, the frame has every particle once and every
// contact once, named by particle id.
TEST_F(VtkReadback, FrameInPiecesJoinsToTheWholeSystem) {
  Snapshot piece0 = snap_, piece1 = snap_;
  piece0.particles = {snap_.particles[0], snap_.particles[2], snap_.particles[3]};
  piece0.contacts = {snap_.contacts[1]};
  piece0.contacts[0].i = 1;  // sphere 2 on the floor
  piece1.particles = {snap_.particles[1], snap_.particles[0]};  // its own, then the partner
  piece1.contacts = {snap_.contacts[0]};
  piece1.contacts[0].i = 1;  // the contact as rank 1 lists it: sphere 0 with sphere 1
  piece1.contacts[0].j = 0;
  VtkOutput out(dir_ / "vtk", shapes_);
  int barriers = 0;
  out.write_frame_piece(piece1, 1, walls_, 1, 2, [&] { ++barriers; });
  EXPECT_FALSE(fs::exists(dir_ / "vtk" / "particles.pvd"));  // rank 1 writes no series
  out = VtkOutput(dir_ / "vtk", shapes_);
  out.write_frame_piece(piece0, 3, walls_, 0, 2, [&] { ++barriers; });
  EXPECT_EQ(barriers, 2);
  const fs::path d = dir_ / "vtk";
  const json r = read_back({d / "particles_000000.pvtu", d / "contacts_000000.pvtu", d / "shapes_000000.pvtu",
                            d / "particles.pvd"});
  ASSERT_FALSE(r.is_null());
  const json& particles = r.at((d / "particles_000000.pvtu").string());
  EXPECT_EQ(particles["cells"], 4);
  std::vector<double> ids = values(particles["point_data"]["id"]);
  std::sort(ids.begin(), ids.end());
  EXPECT_EQ(ids, (std::vector<double>{10, 11, 12, 42}));
  const json& contacts = r.at((d / "contacts_000000.pvtu").string());
  EXPECT_EQ(contacts["cells"], 2);
  EXPECT_EQ(values(contacts["cell_data"]["i"]), (std::vector<double>{12, 10}));
  EXPECT_EQ(values(contacts["cell_data"]["j"]), (std::vector<double>{-1, 11}));
  EXPECT_EQ(r.at((d / "shapes_000000.pvtu").string())["cells"], 24);  // the cross, once
  EXPECT_EQ(r.at((d / "particles.pvd").string())["files"], json({"particles_000000.pvtu"}));
  EXPECT_TRUE(fs::exists(d / "walls_000000.vtu"));
}

TEST_F(VtkReadback, EmptySnapshotIsAValidFile) {
  write_particles_vtu(dir_ / "particles.vtu", Snapshot{});
  write_contacts_vtu(dir_ / "contacts.vtu", Snapshot{});
  const json r = read_back({dir_ / "particles.vtu", dir_ / "contacts.vtu"});
  ASSERT_FALSE(r.is_null());
  EXPECT_EQ(r.at((dir_ / "particles.vtu").string())["points"], 0);
  EXPECT_EQ(r.at((dir_ / "contacts.vtu").string())["cells"], 0);
}

}  // namespace
}  // namespace talus::io
