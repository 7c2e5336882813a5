#pragma once
// Box-box contact by the separating axis test: the 3 + 3 face normals and 9 edge-edge
// directions (Gottschalk et al. 1996; Ericson 2005, Sec. 4.4.1). The axis of least overlap
// gives depth and normal; face axes win ties and, when warm-started, the previous axis is
// kept while within 0.5 % of the least overlap, so the normal does not flip between nearly
// equal faces from step to step (a flipping normal corrupts tangential history).
//   box_box_sat(...)     : the axis test alone; a warm axis that still separates is tried first
//                          (a cached separating axis: one axis test for a lasting gap)
//   box_box_contact(...) : single contact point; for a face axis C is the centroid of the
//                          deepest clipped manifold points (manifold.h), for an edge pair the
//                          midpoint of the closest points of the two edges.
//   box_box_edge_points(): the closest points of the two supporting edges of an edge axis
#include "talus/collide/convex_contact.h"
#include "talus/collide/oriented_box.h"

namespace talus {

struct BoxBoxSat {
  bool separated = false;
  double depth = 0;  ///< least overlap (m); when separated, minus a gap found (a lower bound of the distance)
  Vec3 normal;       ///< unit, from B to A (world)
  int axis = -1;     ///< 0-2: faces of A, 3-5: faces of B, 6 + 3i + j: edge i of A x edge j of B
};

BoxBoxSat box_box_sat(const OrientedBox& a, const OrientedBox& b, int warm_axis = -1);
BoxBoxSat box_box_sat(const Vec3& half_a, const Pose& pose_a, const Vec3& half_b, const Pose& pose_b,
                      int warm_axis = -1);

// A lasting contact keeps its SAT axis (cached separating axes): box_box_axis_reserve bounds how
// far the two boxes may move (the sum of both boxes' largest point displacements, m) before any
// other axis could displace `axis` from what box_box_sat(a, b, axis) returns, given that the two
// rotation angles sum to at most turn_per_travel (rad/m) times that motion. Until then
// box_box_sat_on_axis gives the same answer from that axis alone (false: the axis is degenerate).
double box_box_axis_reserve(const OrientedBox& a, const OrientedBox& b, int axis, double turn_per_travel);
bool box_box_sat_on_axis(const OrientedBox& a, const OrientedBox& b, int axis, BoxBoxSat& out);
// box_box_sat and, for touching boxes, box_box_axis_reserve of its axis from the same overlaps
// (0 when separated): a renewed reserve costs no second set-up of the 15 axes.
BoxBoxSat box_box_sat_with_reserve(const OrientedBox& a, const OrientedBox& b, int warm_axis, double turn_per_travel,
                                   double* reserve);

PartContact box_box_contact(const OrientedBox& a, const OrientedBox& b, ContactCache* warm = nullptr);
PartContact box_box_contact(const Vec3& half_a, const Pose& pose_a, const Vec3& half_b, const Pose& pose_b,
                            ContactCache* warm = nullptr);

// Deepest points for a non-face axis (or a face clip emptied by rounding) along sat.normal:
// point_a on A, point_b on B.
void box_box_edge_points(const OrientedBox& a, const OrientedBox& b, const BoxBoxSat& sat, Vec3& point_a,
                         Vec3& point_b);

}  // namespace talus
