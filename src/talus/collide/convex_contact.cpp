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

PartContact crust_contact(const ConvexShape& a, const Pose& pa, const ConvexShape& b, const Pose& pb,
                              ContactCache* warm) {
  const PosedSupport ca{&a.core, pa, 0.0}, cb{&b.core, pb, 0.0};
  const double crusts = a.crust + b.crust;
  GjkOptions opt;
  opt.margin = crusts;
  opt.scale = a.bounding_radius + b.bounding_radius;
  opt.warm_direction = warm && norm2(warm->separation) > 0 ? warm->separation : pa.position - pb.position;
  const Box* box_a = std::get_if<Box>(&a.core);
  const Box* box_b = std::get_if<Box>(&b.core);
  const bool boxes = box_a && box_b;
  Simplex last;
  if (boxes && warm && warm->simplex != 0) {
    last = box_simplex(warm->simplex, *box_a, pa, *box_b, pb);
    opt.warm_simplex = &last;
  }
  const GjkResult r = gjk_distance(ca, cb, opt);
  if (warm) warm->simplex = boxes && warm->keep_simplex ? box_simplex_code(r.simplex, pa, pb) : 0;
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
    g.point_a = r.point_a - g.normal * a.crust;
    g.point_b = r.point_b + g.normal * b.crust;
    return finish_contact(g);
  }
  // Cores intersect: depth of the rounded shapes = core penetration + both crusts.
  const EpaResult e = epa_penetration(ca, cb, r.simplex, opt.scale);
  g.iterations += e.iterations;
  if (e.ok) {
    g.method = ContactMethod::kCrustEpa;
    g.normal = -e.normal;
    g.delta_n = e.depth + crusts;
    g.point_a = e.point_a - g.normal * a.crust;
    g.point_b = e.point_b + g.normal * b.crust;
  } else {
    // Flat difference (e.g. two coincident sphere centres): overlap along the centre line,
    // measured by the supports; never NaN.
    g.method = ContactMethod::kFallback;
    g.normal = normalized_or_zero(pa.position - pb.position);
    if (norm2(g.normal) == 0) g.normal = Vec3{0, 0, 1};
    const PosedSupport sa{&a.core, pa, a.crust}, sb{&b.core, pb, b.crust};
    g.point_a = sa.support(-g.normal);
    g.point_b = sb.support(g.normal);
    g.delta_n = dot(g.point_b - g.point_a, g.normal);
  }
  if (warm) warm->separation = Vec3{};  // no separating vector to reuse
  return finish_contact(g);
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
