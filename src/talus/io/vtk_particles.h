#pragma once
// ParaView output of particles, two files per frame:
//   particles_*.vtu : one VTK_VERTEX per particle at its centre, particle data as point data
//                     (for ParaView's Glyph filter: Sphere glyph, scale array "radius",
//                     scale factor 2 since the glyph source has unit diameter);
//   shapes_*.vtu    : the true surface of every particle whose shape is not a plain sphere,
//                     as triangles (vtk_shape_mesh.h) placed by the particle's pose, with the
//                     particle data repeated as cell data (plus "part": the composite part).
// Arrays (both files): id (UInt32), species, shape (Int32), velocity, angular_velocity (m/s,
// rad/s, Float64 x3), orientation (Float64 x4: w, x, y, z, body to world), radius (m),
// mass (kg), fixed (UInt8, 1 for fixed particles).
// Files are written atomically (io/atomic_file.h): a reader never sees half a frame.
#include <filesystem>
#include <vector>

#include "talus/analysis/snapshot.h"
#include "talus/io/vtk_shape_mesh.h"
#include "talus/io/vtk_xml.h"
#include "talus/shape/composite_shape.h"

namespace talus::io {

void write_particles_vtu(const std::filesystem::path& path, const Snapshot& snapshot);

// shapes[particle.shape] is the particle's shape; an index outside the table throws
// std::out_of_range. Particles whose shape is a plain sphere (is_plain_sphere) add no cells.
void write_shapes_vtu(const std::filesystem::path& path, const Snapshot& snapshot,
                      const std::vector<CompositeShape>& shapes, const MeshResolution& resolution = {});

// The grids behind those files, of the first `count` particles (a rank's piece, vtk_output.h).
VtuGrid particles_grid(const Snapshot& snapshot, std::size_t count);
VtuGrid shapes_grid(const Snapshot& snapshot, std::size_t count, const std::vector<CompositeShape>& shapes,
                    const MeshResolution& resolution = {});

}  // namespace talus::io
