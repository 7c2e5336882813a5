#pragma once
// Narrow-phase reuse for touching box pairs (the idea of Box2D v3's contact recycling
// and Bullet's persistent manifolds, kept exact): a touching part pair keeps the feature of its
// last full SAT query, the axis (reference face, or edge pair; box_box.h), with a reserve of
// motion (box_box_axis_reserve) within which no other of the 15 axes can take over. While the
// two bodies' travels (PlacedBodies::travel: displacement plus the chord of the turn) stay below
// it, the pair skips its capsule cull and the 15-axis search and rebuilds its contact from the
// stored feature alone (box_box_sat_on_axis, then the clip or edge points of that feature): the
// very code the full query answers with, so the points are the full query's to the bit. Past
// the reserve, on a new contact or on a feature the points no longer carry, the full query runs
// and renews the reserve.
//
// Being exact, reuse changes no result: a restart (whose budgets start empty), another rank
// count or `contact.narrow_phase_reuse = false` give the same bits, and nothing is checkpointed.
//
// One approximation goes on top (`contact.manifold_refit`, a fraction f): a face contact that
// keeps its axis also keeps the features its points were clipped from, and rebuilds each point
// from them (box_box_refit: a vertex, an edge-plane or a line-face intersection) instead of
// clipping the incident face again, until the bodies have travelled f times the deepest overlap
// since the clip. The points are the clip's while its outcome keeps those features; a point the
// clip would add in the meantime (a vertex coming down through the reference face) is missed,
// with an overlap below the motion since the clip, about 2 f of the deepest. f = 0 (the
// default) keeps reuse exact; edge-edge contacts are always exact.
//
// Or (`contact.manifold_recycle`, a travel in metres) a touching pair, face or edge contact,
// keeps its points as anchors fixed in the two boxes and serves them for that travel after they
// were computed, with no SAT and no clip: the overlap along the normal, which turns with box i,
// follows the anchors (from_anchors). The two approximations exclude each other.
#include "talus/collide/box_box.h"
#include "talus/world/pair_budgets.h"
#include "talus/world/sub_contacts.h"

namespace talus {

// How a part pair has moved since it was last looked at.
struct PairMotion {
  double travelled;        ///< m, sum of the two bodies' travels (PlacedBodies::travel)
  double turn_per_travel;  ///< rad/m, bound on the two rotation angles per metre of travel
};

// True while the stored feature of a touching pair still answers the full query: the budget
// holds a reserve for `stored_axis` (the axis of the pair's points of last step) not yet spent.
inline bool feature_reusable(const PartBudget& budget, int stored_axis, double travelled) {
  return stored_axis >= 0 && stored_axis == budget.axis && travelled < budget.until;
}

// What a touching box pair may reuse: its stored feature (`on`) and, for a face contact, its
// stored points for a travel of `refit` times their deepest overlap.
struct Reuse {
  bool on;
  double refit;
  bool gjk_warm_start;  ///< WorldSettings::gjk_warm_start
  double recycle = 0;   ///< m, WorldSettings::manifold_recycle
};

// True while the stored points of a face contact may be refit rather than clipped: the axis is
// still the SAT's answer and the travel since the clip is within the refit margin.
inline bool refit_allowed(bool reuse, const PartBudget& budget, int stored_axis, double travelled) {
  return reuse && stored_axis >= 0 && stored_axis < 6 && feature_reusable(budget, stored_axis, travelled) &&
         budget.refit_allowed(travelled);
}

// True while the anchored points of a touching pair may be recycled: its stored feature is still
// the SAT's answer and the travel since they were computed is within the recycle margin (the
// margin shares PartBudget::refit_slack with the refit, which it excludes).
inline bool recycle_allowed(const Reuse& reuse, const PartBudget& budget, int stored_axis, double travelled) {
  return reuse.on && reuse.recycle > 0 && feature_reusable(budget, stored_axis, travelled) &&
         budget.refit_allowed(travelled);
}

// A box's local coordinates of a world point; a local direction turned into the world.
inline Vec3 in_box(const OrientedBox& box, const Vec3& world) {
  const Vec3 d = world - box.centre;
  return {dot(d, box.axis[0]), dot(d, box.axis[1]), dot(d, box.axis[2])};
}
inline Vec3 turned_with(const OrientedBox& box, const Vec3& local) {
  return box.axis[0] * local.x + box.axis[1] * local.y + box.axis[2] * local.z;
}

// The anchors of a contact point of boxes a (body i) and b: half the overlap either side of
// the point along the normal (from b towards a), and the normal, in the boxes' frames.
inline PointAnchors anchors_of(const OrientedBox& a, const OrientedBox& b, const Vec3& normal, const Vec3& point,
                               double overlap) {
  const Vec3 half_depth = normal * (0.5 * overlap);
  return {in_box(a, point - half_depth), in_box(b, point + half_depth),
          {dot(normal, a.axis[0]), dot(normal, a.axis[1]), dot(normal, a.axis[2])}};
}

// A point served from its anchors as the boxes stand now. The overlap is the anchors'
// separation along the normal, which turns with box a: an approach along the normal changes it
// exactly, a slide along the contact plane not at all, and a turn by a small angle phi by about
// phi times the slide it causes. The point is the anchors' midpoint.
struct AnchoredPoint {
  Vec3 normal, point;
  double overlap;
};
inline AnchoredPoint from_anchors(const OrientedBox& a, const OrientedBox& b, const PointAnchors& k) {
  const Vec3 deepest_i = a.centre + turned_with(a, k.deepest_i), deepest_j = b.centre + turned_with(b, k.deepest_j);
  const Vec3 normal = turned_with(a, k.normal_in_i);
  return {normal, (deepest_i + deepest_j) * 0.5, dot(deepest_j - deepest_i, normal)};
}

// Where a box pair's SAT answer came from.
enum class SatSource {
  stored_feature,  ///< a touching pair's stored axis, within its reserve
  apart_axis,      ///< the axis that separated the pair last time, which still does
  full,            ///< the 15-axis search
};

// The SAT of two touching boxes. With `reuse`, a lasting contact evaluates its stored axis alone
// while feature_reusable says it must still win; otherwise the full test runs, warm-started from
// that axis, and (with `reuse`) renews the reserve.
inline BoxBoxSat lasting_box_sat(const OrientedBox& a, const OrientedBox& b, int stored_axis, const PairMotion& motion,
                                 bool reuse, PartBudget& budget, SatSource* source) {
  BoxBoxSat sat;
  *source = SatSource::stored_feature;
  if (reuse && feature_reusable(budget, stored_axis, motion.travelled) && box_box_sat_on_axis(a, b, stored_axis, sat))
    return sat;
  // Woken after a gap: the axis that showed it usually still does (any axis's separation bounds
  // the distance from below); a pair it no longer separates gets the full query, unwarmed.
  if (const int apart_axis = budget.separating_axis();
      reuse && stored_axis < 0 && apart_axis >= 0 && box_box_sat_on_axis(a, b, apart_axis, sat) && sat.separated) {
    budget.sleep(motion.travelled, 0.0, apart_axis);  // the caller extends it by the gap
    *source = SatSource::apart_axis;
    return sat;
  }
  *source = SatSource::full;
  double reserve = 0;
  sat = reuse ? box_box_sat_with_reserve(a, b, stored_axis, motion.turn_per_travel, &reserve)
              : box_box_sat(a, b, stored_axis);
  if (sat.separated)
    budget.sleep(motion.travelled, 0.0, reuse ? sat.axis : -1);  // the caller extends it by the gap
  else if (reuse)
    budget = {motion.travelled + reserve, sat.axis};
  else
    budget.sleep(motion.travelled, 0.0);  // awake: touching pairs are tested every step
  return sat;
}

}  // namespace talus
