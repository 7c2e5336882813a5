#pragma once
// The corners of a polyhedron given as a mesh file: `mesh = "FILE.obj"` or `"FILE.stl"`
// (io/triangle_mesh_file.h), relative to the scenario file's folder, with `mesh_scale` (default 1)
// multiplying its coordinates, for meshes drawn in millimetres. The surface must be closed and
// convex (shape/convex_surface.h): a polyhedron is the hull of its corners, and a mesh that is
// not that hull would silently become a different shape.
#include <string>
#include <vector>

#include "talus/io/scenario_file.h"
#include "talus/math/vec3.h"

namespace talus {

// The mesh's vertices (m), at least 4. Errors are the key's, `FILE:LINE: KEY.mesh: ...`, and go
// on to name the mesh file: `... species.rock.mesh: rock.stl: the surface is not closed: ...`.
std::vector<Vec3> read_mesh_vertices(const io::ScenarioFile& f, const std::string& key);

}  // namespace talus
