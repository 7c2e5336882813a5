#pragma once
// Narrow phase for one pair of convex parts under world poses.
//
//   PartContact narrow_phase(a, pose_a, b, pose_b, cache, options)
// dispatches to an analytic path (sphere-sphere, sphere-box, sharp box-box SAT) or to the
// crust method: GJK distance between the cores, overlap = c_A + c_B - distance (GRAINS3D,
// Wachs et al. 2012). Cores that intersect (overlap beyond the crusts) go to EPA on the cores
// (depth = core depth + c_A + c_B), and if even that fails to a support-function estimate, so
// the caller never sees NaN; `method` says which path answered.
//
// Conventions (Huet et al. 2021, Fig. 2): normal is the unit vector from B to A (force on A is
// along +normal); point_a is the deepest point of A inside B, point_b that of B inside A;
// delta_n = |point_a - point_b| > 0 when penetrating; point C is their midpoint.
// ContactCache carries the last separation vector / SAT axis per pair to warm-start the next step.
#include <cstdint>

#include "talus/collide/oriented_box.h"
#include "talus/shape/convex_shape.h"
#include "talus/shape/pose.h"

namespace talus {

enum class ContactMethod : std::uint8_t {
  kNone,          ///< no query ran
  kSphereSphere,  ///< analytic
  kSphereBox,     ///< analytic, sphere vs box rounded by its crust
  kBoxBoxSat,     ///< separating axes, sharp boxes
  kCrustGjk,      ///< GJK distance between cores
  kCrustEpa,      ///< cores intersect: EPA on the cores
  kFallback,      ///< EPA failed: support-function estimate along the centre line
  kPlane,         ///< convex vs half-space
  kSphereCylinder,  ///< analytic, sphere vs cylinder rounded by its crust
};

struct PartContact {
  bool touching = false;  ///< delta_n > 0
  double delta_n = 0;     ///< overlap (m); negative = gap when known (may be a lower bound)
  Vec3 normal;            ///< unit, from B to A (world)
  Vec3 point;             ///< contact point C = midpoint of point_a and point_b (m)
  Vec3 point_a;           ///< deepest point of A inside B (m)
  Vec3 point_b;           ///< deepest point of B inside A (m)
  ContactMethod method = ContactMethod::kNone;
  int iterations = 0;     ///< GJK + EPA iterations (crust paths)
};

struct ContactCache {
  Vec3 separation;    ///< last core separation vector point_a - point_b, world (m); zero = cold
  int sat_axis = -1;  ///< last box-box separating axis (0..14), -1 = none
  std::uint32_t simplex = 0;  ///< two box cores' last GJK simplex (box_simplex.h), 0 = none
  bool keep_simplex = false;  ///< whether to return the final simplex in `simplex` (its code costs a query)
};

struct NarrowPhaseOptions {
  bool sharp_boxes = false;  ///< box-box by SAT on the nominal sharp boxes instead of the crust
};

PartContact narrow_phase(const ConvexShape& a, const Pose& pose_a, const ConvexShape& b, const Pose& pose_b,
                             ContactCache* warm = nullptr, const NarrowPhaseOptions& options = {});

// Whether two parts come within `clearance` of each other: narrow_phase's answer to
// delta_n > -clearance, where the crust method stops at GJK's verdict instead of measuring
// the depth by EPA (insertion asks only whether a body fits).
bool parts_within(const ConvexShape& a, const Pose& pose_a, const ConvexShape& b, const Pose& pose_b,
                  double clearance, const NarrowPhaseOptions& options = {});

// The crust method alone (any pair of shapes), for tests and for callers that want one model.
PartContact crust_contact(const ConvexShape& a, const Pose& pose_a, const ConvexShape& b, const Pose& pose_b,
                              ContactCache* warm = nullptr);

// The crust method for two box cores already placed in the world (their axes as vectors): the
// answer of crust_contact to GJK's tolerance, without a quaternion per support query. scale is
// the two parts' bounding radii summed, as crust_contact uses.
PartContact crust_box_box_contact(const OrientedBox& core_a, double crust_a, const OrientedBox& core_b,
                                  double crust_b, double scale, ContactCache* warm = nullptr);

// Fills point from point_a/point_b, sets touching; swaps roles A<->B when flip is true.
PartContact finish_contact(PartContact g, bool flip = false);

}  // namespace talus
