#pragma once
// Closed-form contact for simple pairs, same conventions as narrow_phase (convex_contact.h):
//   sphere_sphere_contact   : two spheres
//   sphere_box_contact      : sphere (A) vs box (B) rounded by rounding_b (its crust; 0 = sharp)
//   sphere_cylinder_contact : sphere (A) vs cylinder (B, axis local z) rounded by rounding_b
//   convex_plane_contact    : any contact shape (A) vs a half-space (B), deepest point = support
//                             along -normal
#include "talus/collide/convex_contact.h"

namespace talus {

// The solid half-space dot(normal, x) <= offset; normal points out into the free side.
struct HalfSpace {
  Vec3 normal;        ///< unit
  double offset = 0;  ///< (m)
};

PartContact sphere_sphere_contact(double radius_a, const Vec3& centre_a, double radius_b, const Vec3& centre_b);
PartContact sphere_box_contact(double radius_a, const Vec3& centre_a, const Vec3& core_half_extents_b,
                                   double rounding_b, const Pose& pose_b);
PartContact sphere_cylinder_contact(double radius_a, const Vec3& centre_a, double core_radius_b,
                                    double core_half_height_b, double rounding_b, const Pose& pose_b);
PartContact convex_plane_contact(const ConvexShape& a, const Pose& pose_a, const HalfSpace& plane);

}  // namespace talus
