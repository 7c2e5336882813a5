#include "talus/collide/convex_contact.h"

#include <cmath>
#include <utility>

#include "talus/collide/box_box.h"
#include "talus/collide/box_simplex.h"
#include "talus/collide/convex_contact_analytic.h"
#include "talus/collide/gjk.h"
#include "talus/collide/gjk_epa.h"

namespace talus {

PartContact finish_contact(PartContact g, bool flip) {
  if (flip) {
    g.normal = -g.normal;
    std::swap(g.point_a, g.point_b);
  }
  g.point = (g.point_a + g.point_b) * 0.5;  // Huet et al. 2021, Fig. 2: C is the midpoint of AB
  g.touching = g.delta_n > 0;
  return g;
}

namespace {

// The crust method over any two core supports (Wachs et al. 2012). `codec`, when both cores are
// boxes, turns a GJK simplex into corner ids and back (box_simplex.h) for the warm start.
template <class SupportA, class SupportB, class Codec>
PartContact crust_of_cores(const SupportA& ca, double crust_a, const SupportB& cb, double crust_b, double scale,
                           ContactCache* warm, const Codec* codec) {
  const double crusts = crust_a + crust_b;
  GjkOptions opt;
  opt.margin = crusts;
  opt.scale = scale;
  opt.warm_direction = warm && norm2(warm->separation) > 0 ? warm->separation : ca.centre() - cb.centre();
  const bool from_simplex = codec && warm && warm->simplex != 0;
  const Simplex last = from_simplex ? codec->simplex(warm->simplex) : Simplex{};  // built in place
  if (from_simplex) opt.warm_simplex = &last;
  const GjkResult r = gjk_distance(ca, cb, opt);
  if (warm) warm->simplex = codec && warm->keep_simplex ? codec->code(r.simplex) : 0;
  PartContact g;
  g.iterations = r.iterations;
  if (r.beyond_margin) {
    if (warm) warm->separation = opt.warm_direction;  // still separating: keep it
    g.method = ContactMethod::kCrustGjk;
    g.delta_n = crusts - r.distance;  // r.distance is a lower bound here
    g.normal = normalized_or_zero(opt.warm_direction);
    return g;
  }
  if (!r.intersecting) {
    // Crust method (Wachs et al. 2012): overlap = c_A + c_B - core distance, normal along the
    // closest-point vector, deepest points = core witnesses pushed out through their crusts.
    if (warm) warm->separation = r.separation;
    g.method = ContactMethod::kCrustGjk;
    g.normal = r.separation / r.distance;
    g.delta_n = crusts - r.distance;
    g.point_a = r.point_a - g.normal * crust_a;
    g.point_b = r.point_b + g.normal * crust_b;
    return finish_contact(g);
  }
  // Cores intersect: depth of the rounded shapes = core penetration + both crusts.
  const EpaResult e = epa_penetration(ca, cb, r.simplex, opt.scale);
  g.iterations += e.iterations;
  if (e.ok) {
    g.method = ContactMethod::kCrustEpa;
    g.normal = -e.normal;
    g.delta_n = e.depth + crusts;
    g.point_a = e.point_a - g.normal * crust_a;
    g.point_b = e.point_b + g.normal * crust_b;
  } else {
    // Flat difference (e.g. two coincident sphere centres): overlap along the centre line,
    // measured by the supports of the rounded shapes; never NaN.
    g.method = ContactMethod::kFallback;
    g.normal = normalized_or_zero(ca.centre() - cb.centre());
    if (norm2(g.normal) == 0) g.normal = Vec3{0, 0, 1};
    g.point_a = ca.support(-g.normal) + normalized_or_zero(-g.normal) * crust_a;
    g.point_b = cb.support(g.normal) + normalized_or_zero(g.normal) * crust_b;
    g.delta_n = dot(g.point_b - g.point_a, g.normal);
  }
  if (warm) warm->separation = Vec3{};  // no separating vector to reuse
  return finish_contact(g);
}

struct PosedBoxCodec {
  const Box &a, &b;
  const Pose &pa, &pb;
  Simplex simplex(std::uint32_t code) const { return box_simplex(code, a, pa, b, pb); }
  std::uint32_t code(const Simplex& s) const { return box_simplex_code(s, pa, pb); }
};

struct OrientedBoxCodec {
  const OrientedBox &a, &b;
  Simplex simplex(std::uint32_t code) const { return box_simplex(code, a, b); }
  std::uint32_t code(const Simplex& s) const { return box_simplex_code(s); }
};

}  // namespace

PartContact crust_contact(const ConvexShape& a, const Pose& pa, const ConvexShape& b, const Pose& pb,
                              ContactCache* warm) {
  const PosedSupport ca{&a.core, pa, 0.0}, cb{&b.core, pb, 0.0};
  const Box* box_a = std::get_if<Box>(&a.core);
  const Box* box_b = std::get_if<Box>(&b.core);
  const double scale = a.bounding_radius + b.bounding_radius;
  if (!(box_a && box_b))
    return crust_of_cores(ca, a.crust, cb, b.crust, scale, warm, static_cast<const PosedBoxCodec*>(nullptr));
  const PosedBoxCodec codec{*box_a, *box_b, pa, pb};
  return crust_of_cores(ca, a.crust, cb, b.crust, scale, warm, &codec);
}

PartContact crust_box_box_contact(const OrientedBox& core_a, double crust_a, const OrientedBox& core_b,
                                  double crust_b, double scale, ContactCache* warm) {
  const OrientedBoxSupport ca{&core_a}, cb{&core_b};
  const OrientedBoxCodec codec{core_a, core_b};
  return crust_of_cores(ca, crust_a, cb, crust_b, scale, warm, &codec);
}

PartContact narrow_phase(const ConvexShape& a, const Pose& pa, const ConvexShape& b, const Pose& pb,
                             ContactCache* warm, const NarrowPhaseOptions& options) {
  const ShapeKind ka = a.kind(), kb = b.kind();
  if (ka == ShapeKind::kSphere && kb == ShapeKind::kSphere)
    return sphere_sphere_contact(a.crust, pa.position, b.crust, pb.position);
  if (ka == ShapeKind::kSphere && kb == ShapeKind::kBox)
    return sphere_box_contact(a.crust, pa.position, std::get<Box>(b.core).half_extents, b.crust, pb);
  if (ka == ShapeKind::kBox && kb == ShapeKind::kSphere)
    return finish_contact(sphere_box_contact(b.crust, pb.position, std::get<Box>(a.core).half_extents, a.crust, pa),
                          true);
  if (ka == ShapeKind::kSphere && kb == ShapeKind::kCylinder) {
    const Cylinder& c = std::get<Cylinder>(b.core);
    return sphere_cylinder_contact(a.crust, pa.position, c.radius, c.half_height, b.crust, pb);
  }
  if (ka == ShapeKind::kCylinder && kb == ShapeKind::kSphere) {
    const Cylinder& c = std::get<Cylinder>(a.core);
    return finish_contact(sphere_cylinder_contact(b.crust, pb.position, c.radius, c.half_height, a.crust, pa), true);
  }
  if (ka == ShapeKind::kBox && kb == ShapeKind::kBox && (options.sharp_boxes || a.crust + b.crust == 0))
    return box_box_contact(std::get<Box>(a.geometry).half_extents, pa, std::get<Box>(b.geometry).half_extents, pb, warm);
  return crust_contact(a, pa, b, pb, warm);
}

bool parts_within(const ConvexShape& a, const Pose& pa, const ConvexShape& b, const Pose& pb, double clearance,
                  const NarrowPhaseOptions& options) {
  const ShapeKind ka = a.kind(), kb = b.kind();
  const bool crust_method = ka != ShapeKind::kSphere && kb != ShapeKind::kSphere &&
                            !(ka == ShapeKind::kBox && kb == ShapeKind::kBox && (options.sharp_boxes || a.crust + b.crust == 0));
  if (!crust_method) return narrow_phase(a, pa, b, pb, nullptr, options).delta_n > -clearance;
  // The rounded shapes come within the clearance when their cores do within both crusts and it.
  const PosedSupport ca{&a.core, pa, 0.0}, cb{&b.core, pb, 0.0};
  GjkOptions opt;
  opt.margin = a.crust + b.crust + clearance;
  opt.scale = a.bounding_radius + b.bounding_radius;
  opt.warm_direction = pa.position - pb.position;
  const GjkResult r = gjk_distance(ca, cb, opt);
  return !r.beyond_margin && (r.intersecting || r.distance < opt.margin);
}

}  // namespace talus
