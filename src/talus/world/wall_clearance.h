#pragma once
// Whether a sphere placed at time t would cut into a wall. Random insertion and pouring place
// particles by their (bounding) spheres; one that starts inside a wall is thrown out of it by
// the full stiffness of the overlap in a few steps, far faster than anything in the flow.
#include <vector>

#include "talus/math/vec3.h"
#include "talus/world/wall.h"

namespace talus {

// A bounded wall counts only where the sphere's centre is in front of it and projects onto the
// rectangle widened by the radius, as its contacts do (wall_contacts.h).
bool sphere_cuts_a_wall(const std::vector<Wall>& walls, double t, const Vec3& centre, double radius);

}  // namespace talus
