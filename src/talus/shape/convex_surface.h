#pragma once
// Whether a triangle mesh is the closed surface of a convex solid, so that the convex hull of its
// vertices is the solid the mesh draws, not a filled-in version of something else.
//   closed : every edge belongs to exactly two triangles running along it in opposite
//            directions, which also makes the triangles' orientation consistent;
//   convex : every vertex lies on the convex hull of the vertices, and the surface encloses the
//            hull's volume: a closed surface through points on a convex surface that holds as
//            much as it is that surface (unless it crosses itself).
// Both within a skin of 1e-6 of the mesh's size (its bounding box diagonal): a flat face split
// into triangles whose corners the file's rounding lifts off the plane (binary STL stores
// float32, 6e-8 relative) passes, a dent a contact could feel does not. Being compared with the
// hull rather than with each triangle's plane, sliver and zero-area triangles (three corners in
// a line, as exporters leave beside a vertex in mid-edge) need no special case.
#include "talus/shape/triangle_mesh.h"

namespace talus {

// Throws std::invalid_argument with the first defect found, in the mesh's units:
//   "the surface is not closed: edge (0 0 1)-(1 0 1) belongs to 1 triangle only (a hole or a crack)"
//   "the surface is not convex: vertex (0 0 0.5) lies 0.5 inside the convex hull of the vertices"
void check_closed_convex_surface(const TriangleMesh& mesh);

}  // namespace talus
