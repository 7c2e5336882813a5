#pragma once
// Convex hull of a point cloud (up to a few hundred points): build_convex_hull(points)
// returns the hull vertices, an outward-oriented triangulation (for mass properties) and
// the polygon faces obtained by merging coplanar triangles (for face clipping).
// Incremental hull with a relative tolerance; throws std::invalid_argument when the points
// are (nearly) coplanar, since a flat polyhedron has no volume.
#include <array>
#include <vector>

#include "talus/math/vec3.h"

namespace talus {

struct HullFace {
  std::vector<int> vertices;  ///< polygon, counter-clockwise seen from outside
  Vec3 normal;                ///< outward unit normal
  double offset = 0;          ///< plane: dot(normal, x) == offset (m)
};

struct ConvexHull {
  std::vector<Vec3> vertices;                 ///< hull vertices only (m)
  std::vector<std::array<int, 3>> triangles;  ///< counter-clockwise seen from outside
  std::vector<HullFace> faces;                ///< coplanar triangles merged
};

ConvexHull build_convex_hull(const std::vector<Vec3>& points);

}  // namespace talus
