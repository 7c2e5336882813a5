#pragma once
// ParaView output of walls at time t: one polygon cell per active wall (removed walls are
// left out), counter-clockwise seen from the side the normal points to.
//   bounded wall  : its rectangle, centred at origin_at(t) (a VTK_QUAD);
//   infinite plane: the plane clipped to `box` (usually the domain), a VTK_QUAD when the
//                   section has 4 corners (any axis-aligned plane), else a VTK_POLYGON (3 to 6);
//                   a plane missing the box adds no cell.
// Cell data: wall (Int32, index into `walls`), normal (unit), velocity (m/s, at t),
// material (Int32), bounded (UInt8).
#include <filesystem>
#include <vector>

#include "talus/math/vec3.h"
#include "talus/shape/convex_shape.h"
#include "talus/world/wall.h"

namespace talus::io {

void write_walls_vtu(const std::filesystem::path& path, const std::vector<Wall>& walls, double time,
                     const Aabb& box);

// Section of the plane {x : dot(normal, x - origin) = 0} by the box, ordered counter-clockwise
// about `normal`; empty when the plane misses the box (or only touches an edge or a corner).
std::vector<Vec3> clip_plane_to_box(const Vec3& origin, const Vec3& normal, const Aabb& box);

}  // namespace talus::io
