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

namespace {
// A ball (radius_a, centre_a) against a core rounded by rounding_b, in the core's frame (q: the
// centre there). Outside the core the contact is along the nearest core point `clamped`; inside,
// the ball leaves along `exit_normal` through the nearest face with overlap `exit_overlap`,
// meeting the rounded surface at `exit_surface`.
PartContact ball_against_core(double radius_a, const Vec3& centre_a, const Vec3& q, const Vec3& clamped,
                              const Vec3& exit_normal, double exit_overlap, const Vec3& exit_surface,
                              double rounding_b, const Pose& pose_b, ContactMethod method) {
  PartContact g;
  g.method = method;
  Vec3 n_local, surface_local;
  const double dist = norm(q - clamped);
  if (dist > 0) {
    n_local = (q - clamped) / dist;
    g.delta_n = radius_a + rounding_b - dist;
    surface_local = clamped + n_local * rounding_b;
  } else {
    n_local = exit_normal;
    g.delta_n = exit_overlap;
    surface_local = exit_surface;
  }
  g.normal = pose_b.orientation.rotate(n_local);
  g.point_a = centre_a - g.normal * radius_a;
  g.point_b = pose_b.to_parent(surface_local);
  return finish_contact(g);
}
}  // namespace

PartContact sphere_box_contact(double radius_a, const Vec3& centre_a, const Vec3& core_half_extents_b,
                                   double rounding_b, const Pose& pose_b) {
  const Vec3 q = pose_b.to_child(centre_a);
  const Vec3& h = core_half_extents_b;
  const Vec3 clamped{std::clamp(q.x, -h.x, h.x), std::clamp(q.y, -h.y, h.y), std::clamp(q.z, -h.z, h.z)};
  int k = 0;  // the nearest face, if the centre is inside the core
  for (int i = 1; i < 3; ++i)
    if (h[i] - std::abs(q[i]) < h[k] - std::abs(q[k])) k = i;
  Vec3 exit, surface = q;
  exit[k] = q[k] >= 0 ? 1 : -1;
  surface[k] = exit[k] * (h[k] + rounding_b);
  return ball_against_core(radius_a, centre_a, q, clamped, exit, radius_a + rounding_b + h[k] - std::abs(q[k]),
                           surface, rounding_b, pose_b, ContactMethod::kSphereBox);
}

// A sphere part (the hub of a tetrapod, the cap of a rod) against a cylinder: in closed form, as
// for boxes. EPA on a point inside a cylinder core walks the flat caps and curved side, whose
// supports round onto one another, and breaks down.
PartContact sphere_cylinder_contact(double radius_a, const Vec3& centre_a, double core_radius_b,
                                    double core_half_height_b, double rounding_b, const Pose& pose_b) {
  const Vec3 q = pose_b.to_child(centre_a);
  const double R = core_radius_b, H = core_half_height_b;
  const double rho = std::sqrt(q.x * q.x + q.y * q.y);
  const Vec3 radial = rho > 0 ? Vec3{q.x / rho, q.y / rho, 0} : Vec3{1, 0, 0};
  const Vec3 clamped{rho > R ? radial.x * R : q.x, rho > R ? radial.y * R : q.y, std::clamp(q.z, -H, H)};
  const bool side = R - rho < H - std::abs(q.z);  // inside, the side is nearer than a cap
  const Vec3 exit = side ? radial : Vec3{0, 0, q.z >= 0 ? 1.0 : -1.0};
  const Vec3 surface = side ? radial * (R + rounding_b) + Vec3{0, 0, q.z} : Vec3{q.x, q.y, exit.z * (H + rounding_b)};
  const double overlap = side ? radius_a + rounding_b + R - rho : radius_a + rounding_b + H - std::abs(q.z);
  return ball_against_core(radius_a, centre_a, q, clamped, exit, overlap, surface, rounding_b, pose_b,
                           ContactMethod::kSphereCylinder);
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
