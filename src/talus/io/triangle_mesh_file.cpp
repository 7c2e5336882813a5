#include "talus/io/triangle_mesh_file.h"

#include <algorithm>
#include <cctype>

#include "talus/io/input_error.h"
#include "talus/io/input_file.h"

namespace talus::io {

TriangleMesh read_triangle_mesh(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension != ".obj" && extension != ".stl")
    throw InputError(path.string() + ": unknown mesh format: expected a Wavefront .obj or an .stl file");
  const std::string bytes = read_input_file(path);
  return welded(extension == ".obj" ? parse_obj_mesh(bytes, path.string()) : parse_stl_mesh(bytes, path.string()));
}

}  // namespace talus::io
