#include "talus/collide/convex_contact_analytic.h"

#include <algorithm>
#include <cmath>

namespace talus {

PartContact sphere_sphere_contact(double radius_a, const Vec3& centre_a, double radius_b, const Vec3& centre_b) {
  const Vec3 d = centre_a - centre_b;
  const double dist = norm(d);
  PartContact g;
  g.method = ContactMethod::kSphereSphere;
  g.normal = dist > 0 ? d / dist : Vec3{0, 0, 1};  // concentric: any direction is as good
  g.delta_n = radius_a + radius_b - dist;
  g.point_a = centre_a - g.normal * radius_a;
  g.point_b = centre_b + g.normal * radius_b;
  return finish_contact(g);
}

PartContact sphere_box_contact(double radius_a, const Vec3& centre_a, const Vec3& core_half_extents_b,
                                   double rounding_b, const Pose& pose_b) {
  const Vec3 q = pose_b.to_child(centre_a);
  const Vec3& h = core_half_extents_b;
  const Vec3 clamped{std::clamp(q.x, -h.x, h.x), std::clamp(q.y, -h.y, h.y), std::clamp(q.z, -h.z, h.z)};
  PartContact g;
  g.method = ContactMethod::kSphereBox;
  Vec3 n_local, surface_local;
  const double dist = norm(q - clamped);
  if (dist > 0) {  // centre outside the core: nearest core point, then out by the rounding
    n_local = (q - clamped) / dist;
    g.delta_n = radius_a + rounding_b - dist;
    surface_local = clamped + n_local * rounding_b;
  } else {  // centre inside the core: leave through the nearest face
    int k = 0;
    for (int i = 1; i < 3; ++i)
      if (h[i] - std::abs(q[i]) < h[k] - std::abs(q[k])) k = i;
    n_local[k] = q[k] >= 0 ? 1 : -1;
    g.delta_n = radius_a + rounding_b + h[k] - std::abs(q[k]);
    surface_local = q;
    surface_local[k] = n_local[k] * (h[k] + rounding_b);
  }
  g.normal = pose_b.orientation.rotate(n_local);
  g.point_a = centre_a - g.normal * radius_a;
  g.point_b = pose_b.to_parent(surface_local);
  return finish_contact(g);
}

PartContact convex_plane_contact(const ConvexShape& a, const Pose& pose_a, const HalfSpace& plane) {
  const PosedSupport sa{&a.core, pose_a, a.crust};
  PartContact g;
  g.method = ContactMethod::kPlane;
  g.normal = plane.normal;
  g.point_a = sa.support(-plane.normal);
  g.delta_n = plane.offset - dot(plane.normal, g.point_a);
  g.point_b = g.point_a + plane.normal * g.delta_n;
  return finish_contact(g);
}

}  // namespace talus
