#pragma once
// Contact manifolds: up to 4 points per pair when a face lies against a face or an edge
// against a face (goes beyond Huet et al. 2021, who use one point for these cases).
//   box_box_manifold(...)      : reference face = face of the SAT axis; the most anti-parallel
//                                face of the other box is clipped against the reference face's
//                                side planes (Sutherland-Hodgman, on fixed arrays: no heap in
//                                the hot path); points below the reference face are kept.
//                                Edge-edge axes give one point.
//   convex_plane_manifold(...) : box / polyhedron vertices below a half-space (nominal sharp
//                                geometry); spheres and cylinders give the single support point.
//   contact_manifold(...)      : dispatch; box-box by SAT+clipping, otherwise narrow_phase's
//                                single point (single-point mode stays available everywhere).
// More than 4 candidates are reduced to the deepest plus the three that span the largest area.
// feature_id is stable while the touching features stay the same, so a caller can key
// tangential history per point: box-box (reference face 0-11 << 24 | incident face << 16 |
// incident-edge mask << 8 | side-plane mask), plane: vertex index.
#include <array>
#include <cstdint>

#include "talus/collide/box_box.h"
#include "talus/math/uninitialized_array.h"
#include "talus/collide/convex_contact.h"
#include "talus/collide/convex_contact_analytic.h"

namespace talus {

struct ManifoldPoint {
  double delta_n = 0;           ///< overlap at this point (m)
  Vec3 point;                   ///< midpoint of point_a and point_b (m)
  Vec3 point_a;                 ///< point of A (m)
  Vec3 point_b;                 ///< point of B (m)
  std::uint32_t feature_id = 0; ///< stable id of the touching features
};

struct ContactManifold {
  Vec3 normal;  ///< unit, from B to A, shared by all points
  int count = 0;
  UninitializedArray<ManifoldPoint, 4> points;  ///< [0, count) are set
  ContactMethod method = ContactMethod::kNone;
};

ContactManifold box_box_manifold(const OrientedBox& a, const OrientedBox& b, const BoxBoxSat& sat);
// The one point of an edge-edge SAT axis (sat.axis >= 6, not separated), as box_box_manifold
// gives it: a lasting contact on an edge axis can ask for it without a manifold. Inline, so
// that a caller that needs only the midpoint builds no more.
inline ManifoldPoint box_box_edge_point(const OrientedBox& a, const OrientedBox& b, const BoxBoxSat& sat) {
  Vec3 on_a, on_b;
  box_box_edge_points(a, b, sat, on_a, on_b);
  return {sat.depth, (on_a + on_b) * 0.5, on_a, on_b, 0xFFu << 24 | static_cast<std::uint32_t>(sat.axis)};
}
ContactManifold box_box_manifold(const Vec3& half_a, const Pose& pose_a, const Vec3& half_b, const Pose& pose_b,
                                 const BoxBoxSat& sat);
// The points of a face manifold rebuilt from their feature ids alone, on the boxes as they are
// now: each id names an incident vertex, an incident edge and a reference side plane, or two side
// planes (their line met by the incident face), so each point is one vertex, one line-plane or
// one line-face intersection instead of a clip of the incident face. While the clip's outcome
// keeps these features the points are box_box_manifold's (vertices to the bit, intersections to
// rounding); points that no longer overlap are dropped, as the clip drops them. Points it would
// add are not found: the caller runs the clip again after a bounded motion (box_pair_reuse.h).
// False when the ids do not name such points of one reference and one incident face.
bool box_box_refit(const OrientedBox& a, const OrientedBox& b, const std::uint32_t* feature_ids, int count,
                   ContactManifold& out);
// `placed`, when given, is `a` as a placed box (the caller's axes of pose_a): corners clearly
// above the plane are then skipped before they are placed; the points are the same to the bit.
ContactManifold convex_plane_manifold(const ConvexShape& a, const Pose& pose_a, const HalfSpace& plane,
                                      const OrientedBox* placed = nullptr);
ContactManifold contact_manifold(const ConvexShape& a, const Pose& pose_a, const ConvexShape& b, const Pose& pose_b,
                                 ContactCache* warm = nullptr);

}  // namespace talus
