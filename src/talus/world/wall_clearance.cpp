#include "talus/world/wall_clearance.h"

#include "talus/world/wall_contacts.h"

namespace talus {

bool sphere_cuts_a_wall(const std::vector<Wall>& walls, double t, const Vec3& centre, double radius) {
  for (const Wall& wall : walls) {
    if (!wall.active(t)) continue;
    const Vec3 origin = wall.origin_at(t);
    const double d = dot(centre - origin, wall.normal);
    if (d < radius && (!wall.bounded || d > 0) && wall_faces(wall, origin, centre, radius)) return true;
  }
  return false;
}

}  // namespace talus
