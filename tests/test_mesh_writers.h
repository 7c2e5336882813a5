#pragma once
// Mesh files written by the tests: a cube and its variants as OBJ, ASCII STL and binary STL, in a
// fresh folder per test (test_mesh_files.cpp, test_scenario_mesh_shapes.cpp).
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <bit>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "talus/io/number_format.h"
#include "talus/math/vec3.h"

namespace talus::testing {

// The corners of the cube [-h, h]^3, and its faces counter-clockwise seen from outside.
inline std::vector<Vec3> cube_corners(double h) {
  return {{-h, -h, -h}, {h, -h, -h}, {h, h, -h}, {-h, h, -h}, {-h, -h, h}, {h, -h, h}, {h, h, h}, {-h, h, h}};
}
inline std::vector<std::vector<int>> cube_quads() {
  return {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {3, 0, 4, 7}, {1, 2, 6, 5}};
}
inline std::vector<std::vector<int>> fanned(const std::vector<std::vector<int>>& polygons) {
  std::vector<std::vector<int>> triangles;
  for (const auto& p : polygons)
    for (std::size_t k = 1; k + 1 < p.size(); ++k) triangles.push_back({p[0], p[k], p[k + 1]});
  return triangles;
}

inline std::string point_text(const Vec3& p) {
  return io::format_double(p.x) + " " + io::format_double(p.y) + " " + io::format_double(p.z);
}

inline std::string obj_text(const std::vector<Vec3>& vertices, const std::vector<std::vector<int>>& faces) {
  std::string text = "# written by the tests\no cube\n";
  for (const Vec3& v : vertices) text += "v " + point_text(v) + "\n";
  for (const auto& face : faces) {
    text += "f";
    for (int i : face) text += " " + std::to_string(i + 1);
    text += "\n";
  }
  return text;
}

inline std::string ascii_stl_text(const std::vector<Vec3>& vertices, const std::vector<std::vector<int>>& triangles) {
  std::string text = "solid cube written by the tests\n";
  for (const auto& t : triangles) {
    text += "  facet normal 0 0 0\n    outer loop\n";
    for (int i : t) text += "      vertex " + point_text(vertices[i]) + "\n";
    text += "    endloop\n  endfacet\n";
  }
  return text + "endsolid cube\n";
}

// Little-endian, as the format is; float32 coordinates, so the tests' cubes have corners exact in float.
inline std::string binary_stl_bytes(const std::vector<Vec3>& vertices, const std::vector<std::vector<int>>& triangles,
                                    const std::string& header = "solid but binary") {
  std::string bytes = header;
  bytes.resize(80, ' ');
  auto put = [&](std::uint32_t u) {
    for (int k = 0; k < 4; ++k) bytes.push_back(static_cast<char>((u >> (8 * k)) & 0xff));
  };
  put(static_cast<std::uint32_t>(triangles.size()));
  for (const auto& t : triangles) {
    for (int k = 0; k < 3; ++k) put(0);  // the normal
    for (int i : t)
      for (int k = 0; k < 3; ++k) put(std::bit_cast<std::uint32_t>(static_cast<float>(vertices[i][k])));
    bytes += std::string(2, '\0');  // attribute byte count
  }
  return bytes;
}

// A fresh empty folder per test, removed afterwards.
class MeshFolder : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           ("talus_mesh_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::filesystem::path write(const std::string& name, const std::string& contents) const {
    const std::filesystem::path path = dir_ / name;
    std::ofstream(path, std::ios::binary) << contents;
    return path;
  }

  std::filesystem::path dir_;
};

}  // namespace talus::testing
