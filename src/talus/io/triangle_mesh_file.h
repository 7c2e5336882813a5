#pragma once
// Triangle meshes from files, for polyhedral shapes given as `mesh = "FILE"`:
//   Wavefront OBJ (.obj): `v x y z` vertices and `f` faces of three or more corners, each `i`,
//       `i/t`, `i//n` or `i/t/n`, counted from 1 or backwards from -1 (the last vertex so far);
//       a polygon is fanned into triangles from its first corner. Texture coordinates, normals,
//       groups, objects, smoothing, materials, lines and points are ignored; free-form curves
//       and surfaces are refused.
//   STL (.stl): ASCII (`solid NAME`, then `facet normal ... outer loop`, three `vertex x y z`,
//       `endloop endfacet`, ..., `endsolid`) or binary (an 80-byte header, a little-endian
//       uint32 count n, n records of 50 bytes). A file is binary when its size is 84 + 50 n,
//       since binary headers too may begin with "solid". Facet normals are ignored: the
//       triangles' corner order is what orients them.
// The format is told by the extension, in either case. Errors are InputErrors naming the file,
// and for text the line: `shapes/rock.obj:12: f: vertex 9 does not exist (8 vertices)`.
#include <filesystem>
#include <string>
#include <string_view>

#include "talus/shape/triangle_mesh.h"

namespace talus::io {

// The file's triangles, welded (shape/triangle_mesh.h: STL repeats each vertex per facet).
TriangleMesh read_triangle_mesh(const std::filesystem::path& path);

// The readers, on a file's contents; `name` stands for the file in messages. Raw: vertices as
// written, unused or repeated ones included.
TriangleMesh parse_obj_mesh(std::string_view text, const std::string& name);
TriangleMesh parse_stl_mesh(std::string_view bytes, const std::string& name);

}  // namespace talus::io
