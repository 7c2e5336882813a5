#include "talus/scenario/mesh_shape_reader.h"

#include <stdexcept>

#include "talus/io/input_error.h"
#include "talus/io/triangle_mesh_file.h"
#include "talus/shape/convex_surface.h"

namespace talus {

std::vector<Vec3> read_mesh_vertices(const io::ScenarioFile& f, const std::string& key) {
  const std::filesystem::path path = f.get_path(key + ".mesh");
  const double scale = f.get_or<double>(key + ".mesh_scale", 1.0, io::positive);
  TriangleMesh mesh;
  try {
    mesh = io::read_triangle_mesh(path);
    if (mesh.triangles.empty()) throw std::invalid_argument("no triangles (a polyhedron needs a closed surface)");
    if (mesh.vertices.size() < 4)
      throw std::invalid_argument("a polyhedron needs at least 4 vertices, the mesh has " +
                                  std::to_string(mesh.vertices.size()));
    check_closed_convex_surface(mesh);
  } catch (const io::InputError& e) {  // already `FILE:LINE: message`
    f.fail(key + ".mesh", e.what());
  } catch (const std::invalid_argument& e) {
    f.fail(key + ".mesh", path.string() + ": " + e.what());
  }
  for (Vec3& v : mesh.vertices) v *= scale;
  return mesh.vertices;
}

}  // namespace talus
