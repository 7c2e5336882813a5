// Wavefront OBJ meshes (triangle_mesh_file.h).
#include <algorithm>
#include <array>
#include <charconv>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "talus/io/input_error.h"
#include "talus/io/mesh_text.h"
#include "talus/io/triangle_mesh_file.h"

namespace talus::io {

namespace {

std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (true) {
    i = line.find_first_not_of(" \t\r\f\v", i);
    if (i == std::string_view::npos) return out;
    const std::size_t end = std::min(line.find_first_of(" \t\r\f\v", i), line.size());
    out.push_back(line.substr(i, end - i));
    i = end;
  }
}

// Statements that say nothing about the surface's shape.
const std::set<std::string_view> kIgnored{"vt", "vn", "vp", "o", "g", "s", "mg", "usemtl", "mtllib", "l", "p",
                                          "bevel", "c_interp", "d_interp", "lod", "shadow_obj", "trace_obj",
                                          "usemap", "maplib"};
// Free-form geometry, a surface this reader cannot draw: refused rather than left out.
const std::set<std::string_view> kFreeForm{"cstype", "deg", "bmat", "step", "curv", "curv2", "surf",
                                           "parm", "trim", "hole", "scrv", "sp", "end", "con"};

}  // namespace

TriangleMesh parse_obj_mesh(std::string_view text, const std::string& name) {
  TriangleMesh mesh;
  std::vector<int> face_line;  // of each triangle: positive indices are checked once all vertices are known
  int line_number = 0;
  for (std::size_t start = 0; start < text.size();) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    std::string_view line = text.substr(start, end - start);
    start = end + 1;
    ++line_number;
    line = line.substr(0, line.find('#'));
    const std::vector<std::string_view> w = words(line);
    if (w.empty()) continue;
    const std::string where = name + ":" + std::to_string(line_number) + ": ";
    if (w[0] == "v") {
      // x y z, x y z w (homogeneous) or x y z r g b (a colour, as some scanners write).
      if (w.size() != 4 && w.size() != 5 && w.size() != 7)
        throw InputError(where + "v: expected `v x y z`, got " + std::to_string(w.size() - 1) + " numbers");
      std::vector<double> x;
      for (std::size_t k = 1; k < w.size(); ++k) {
        const std::optional<double> value = finite_number(w[k]);
        if (!value) throw InputError(where + "v: not a finite number: '" + std::string(w[k]) + "'");
        x.push_back(*value);
      }
      const double weight = x.size() == 4 ? x[3] : 1;
      if (weight == 0) throw InputError(where + "v: the weight w must not be zero");
      mesh.vertices.push_back(Vec3{x[0], x[1], x[2]} / weight);
    } else if (w[0] == "f") {
      if (w.size() < 4) throw InputError(where + "f: a face needs at least three vertices");
      std::vector<int> corners;
      for (std::size_t k = 1; k < w.size(); ++k) {
        const std::string_view index_text = w[k].substr(0, w[k].find('/'));  // i of i/t/n
        long index = 0;
        const auto [stop, error] = std::from_chars(index_text.data(), index_text.data() + index_text.size(), index);
        if (error != std::errc() || stop != index_text.data() + index_text.size() || index == 0)
          throw InputError(where + "f: '" + std::string(w[k]) +
                           "' is not a vertex (a whole number from 1, or from -1 backwards)");
        const long count = static_cast<long>(mesh.vertices.size());
        if (index < 0) {
          if (-index > count)
            throw InputError(where + "f: vertex " + std::to_string(index) + " does not exist (" + std::to_string(count) +
                             " vertices so far)");
          index += count + 1;
        }
        if (index > std::numeric_limits<int>::max()) throw InputError(where + "f: vertex " + std::to_string(index) + " does not exist");
        corners.push_back(static_cast<int>(index - 1));
      }
      for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
        mesh.triangles.push_back({corners[0], corners[k], corners[k + 1]});
        face_line.push_back(line_number);
      }
    } else if (kFreeForm.contains(w[0])) {
      throw InputError(where + std::string(w[0]) + ": free-form curves and surfaces are not read; export the surface as "
                               "triangles or polygons");
    } else if (!kIgnored.contains(w[0])) {
      throw InputError(where + "unknown statement '" + std::string(w[0]) + "' (a mesh is read from its v and f lines)");
    }
  }
  const int count = static_cast<int>(mesh.vertices.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int corner : mesh.triangles[t])
      if (corner >= count)
        throw InputError(name + ":" + std::to_string(face_line[t]) + ": f: vertex " + std::to_string(corner + 1) +
                         " does not exist (" + std::to_string(count) + " vertices)");
  return mesh;
}

}  // namespace talus::io
