#pragma once
// A triangulated surface as a mesh file draws it (io/triangle_mesh_file.h), before it becomes a
// polyhedral shape. STL repeats a vertex in every facet that meets at it, and exporters may write
// one point twice with the last digits apart, so the readers weld their raw triangles here.
#include <array>
#include <vector>

#include "talus/math/vec3.h"

namespace talus {

struct TriangleMesh {
  std::vector<Vec3> vertices;                 ///< in the file's units
  std::vector<std::array<int, 3>> triangles;  ///< indices into vertices
};

// The mesh with points closer than 1e-9 of its bounding box's diagonal made one vertex (equal
// ones always), vertices no triangle uses left out, and triangles whose corners became fewer
// than three distinct vertices dropped: they have collapsed to an edge or a point and bound
// nothing. Vertices keep the order of their first use.
TriangleMesh welded(const TriangleMesh& raw);

// The diagonal of the vertices' bounding box: the size tolerances are taken relative to.
double bounding_diagonal(const std::vector<Vec3>& points);

}  // namespace talus
