#pragma once
// Triangle meshes of shape surfaces for ParaView (vtk_particles.h): each convex geometry is
// triangulated in its local frame, a composite in its body frame. The nominal (sharp) geometry
// is drawn, not the crust-rounded contact shape.
//   Box        : 8 vertices, 12 triangles
//   Cylinder   : a prism with `cylinder_sides` sides (default 16: 32 side + 2 x 14 cap triangles)
//   Polyhedron : its hull faces, each fanned into triangles
//   Sphere     : a UV sphere (used only for spheres inside composites; lone spheres are glyphs)
// Triangles are counter-clockwise seen from outside.
#include <array>
#include <vector>

#include "talus/shape/composite_shape.h"
#include "talus/shape/convex_shape.h"

namespace talus::io {

struct SurfaceMesh {
  std::vector<Vec3> vertices;                 ///< m, in the mesh's frame
  std::vector<std::array<int, 3>> triangles;  ///< counter-clockwise seen from outside
  std::vector<int> part;                      ///< composite part index of each triangle
};

struct MeshResolution {
  int cylinder_sides = 16;
  int sphere_rings = 8;      ///< latitude bands of a UV sphere
  int sphere_segments = 16;  ///< longitude segments of a UV sphere
};

SurfaceMesh triangulate(const ConvexGeometry& geometry, const MeshResolution& resolution = {});
// All parts, each placed by its pose in the body frame; part[] records which part.
SurfaceMesh triangulate(const CompositeShape& shape, const MeshResolution& resolution = {});

// True when the shape is one sphere centred on the body origin: drawn as a glyph, not a mesh.
bool is_plain_sphere(const CompositeShape& shape);

}  // namespace talus::io
