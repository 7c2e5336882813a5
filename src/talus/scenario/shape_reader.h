#pragma once
// The shape of a species, from its [species.NAME] table: `shape` = "sphere" (radius, read by
// the caller), "box" (half_extents), "cross" (Huet et al. 2021, Sec. III B: length, width,
// thickness), "cylinder" (radius, height; axis z), "polyhedron" (the convex hull of `vertices`,
// or of the corners of a closed convex triangle mesh, `mesh` = "FILE.obj" or "FILE.stl" relative
// to the scenario's folder, times `mesh_scale`: mesh_shape_reader.h) or "composite" (a union of
// convex parts, [[species.NAME.parts]], each a box, cylinder, sphere or polyhedron with its
// `position` and `orientation` [w, x, y, z] in the body frame, Huet et al. 2021, Sec. II A).
// Named shapes of the literature are composites too: "hexapod" (a 3-D cross: length, width),
// "tetrapod" (four cylindrical arms: length, radius), "stellated_octahedron" (two tetrahedra in
// one cube: size, the cube's side) and "rod" (a spherocylinder along z: length between the caps'
// centres, radius), built by shape/named_shapes.h. Every convex shape takes a `crust`, the
// rounding of GJK's crust method; its default is 5 % of its smallest half dimension.
#include <optional>
#include <string>

#include "talus/io/scenario_file.h"
#include "talus/shape/composite_shape.h"

namespace talus {

// The body of a shaped species, or nothing for a sphere. Errors name the key.
std::optional<CompositeShape> read_body_shape(const io::ScenarioFile& f, const std::string& key);

}  // namespace talus
