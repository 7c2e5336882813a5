#include "talus/collide/manifold.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace talus {
namespace {

Vec3 axis_of(const Pose& p, int k) {
  Vec3 e;
  e[k] = 1;
  return p.orientation.rotate(e);
}

ManifoldPoint make_point(const Vec3& on_a, const Vec3& on_b, double depth, std::uint32_t id) {
  return {depth, (on_a + on_b) * 0.5, on_a, on_b, id};
}

// Keeps at most 4 points: the deepest, the farthest from it, then the two that make the
// largest triangles on either side of that segment (a stable, area-spanning subset).
ContactManifold reduce(const std::vector<ManifoldPoint>& pts, const Vec3& normal, ContactMethod method) {
  ContactManifold m;
  m.normal = normal;
  m.method = method;
  if (pts.size() <= 4) {
    for (const ManifoldPoint& p : pts) m.points[m.count++] = p;
    return m;
  }
  std::size_t i0 = 0, i1 = 0, i2 = 0, i3 = 0;
  for (std::size_t k = 1; k < pts.size(); ++k)
    if (pts[k].delta_n > pts[i0].delta_n) i0 = k;
  double best = -1;
  for (std::size_t k = 0; k < pts.size(); ++k)
    if (const double d = norm2(pts[k].point - pts[i0].point); d > best) best = d, i1 = k;
  const Vec3 e = pts[i1].point - pts[i0].point;
  double hi = 0, lo = 0;
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const double a = dot(cross(e, pts[k].point - pts[i0].point), normal);
    if (a > hi) hi = a, i2 = k;
    if (a < lo) lo = a, i3 = k;
  }
  for (std::size_t k : {i0, i1, i2, i3}) {
    bool dup = false;
    for (int q = 0; q < m.count; ++q) dup = dup || m.points[q].feature_id == pts[k].feature_id;
    if (!dup) m.points[m.count++] = pts[k];
  }
  return m;
}

struct ClipVertex {
  Vec3 p;
  unsigned edges;   // incident-face edges the point lies on (bit per edge)
  unsigned planes;  // reference side planes it lies on (bit per plane)
};

}  // namespace

ContactManifold box_box_manifold(const Vec3& ha, const Pose& pa, const Vec3& hb, const Pose& pb, const BoxBoxSat& sat) {
  ContactManifold out;
  out.normal = sat.normal;
  out.method = ContactMethod::kBoxBoxSat;
  if (sat.separated || sat.axis < 0) return out;
  if (sat.axis >= 6) {  // edge-edge: a single point
    const PartContact g = box_box_contact(ha, pa, hb, pb);
    out.points[0] = make_point(g.point_a, g.point_b, g.delta_n, 0xFFu << 24 | static_cast<unsigned>(sat.axis));
    out.count = 1;
    return out;
  }
  // Reference face: on A (axis < 3) its outward normal is -normal; on B it is +normal.
  const bool ref_is_a = sat.axis < 3;
  const Pose& pr = ref_is_a ? pa : pb;
  const Pose& pi = ref_is_a ? pb : pa;
  const Vec3& hr = ref_is_a ? ha : hb;
  const Vec3& hi = ref_is_a ? hb : ha;
  const int rk = sat.axis % 3;
  const Vec3 m = ref_is_a ? -sat.normal : sat.normal;
  const Vec3 ref_axis = axis_of(pr, rk);
  const int ref_face = 2 * rk + (dot(ref_axis, m) > 0 ? 0 : 1) + (ref_is_a ? 0 : 6);
  const double ref_offset = dot(m, pr.position) + hr[rk];

  // Incident face: the face of the other box most anti-parallel to m.
  int ik = 0;
  double most = 0;
  for (int k = 0; k < 3; ++k)
    if (const double c = std::abs(dot(axis_of(pi, k), m)); c > most) most = c, ik = k;
  const double sgn = dot(axis_of(pi, ik), m) > 0 ? -1.0 : 1.0;
  const int inc_face = 2 * ik + (sgn > 0 ? 0 : 1) + (ref_is_a ? 6 : 0);
  const int k1 = (ik + 1) % 3, k2 = (ik + 2) % 3;
  const Vec3 c = pi.position + axis_of(pi, ik) * (sgn * hi[ik]);
  const Vec3 u = axis_of(pi, k1) * hi[k1], v = axis_of(pi, k2) * hi[k2];
  // Vertex q lies on edges q-1 and q (edge q joins vertex q to q+1).
  std::vector<ClipVertex> poly = {{c + u + v, 0b1001u, 0}, {c - u + v, 0b0011u, 0},
                                  {c - u - v, 0b0110u, 0}, {c + u - v, 0b1100u, 0}};

  // Side planes of the reference face: dot(s, x) <= w.
  int plane = 0;
  for (int k = 0; k < 3; ++k) {
    if (k == rk) continue;
    const Vec3 ax = axis_of(pr, k);
    for (double s : {1.0, -1.0}) {
      const Vec3 n = ax * s;
      const double w = dot(n, pr.position) + hr[k];
      std::vector<ClipVertex> next;
      for (std::size_t q = 0; q < poly.size(); ++q) {
        const ClipVertex& a = poly[q];
        const ClipVertex& b = poly[(q + 1) % poly.size()];
        const double da = dot(n, a.p) - w, db = dot(n, b.p) - w;
        if (da <= 0) next.push_back(a);
        if ((da < 0 && db > 0) || (da > 0 && db < 0)) {
          const double t = da / (da - db);
          next.push_back({a.p + (b.p - a.p) * t, a.edges & b.edges, (a.planes & b.planes) | (1u << plane)});
        }
      }
      poly = std::move(next);
      ++plane;
    }
  }

  std::vector<ManifoldPoint> pts;
  for (const ClipVertex& cv : poly) {
    const double depth = ref_offset - dot(m, cv.p);
    if (depth < 0) continue;
    const Vec3 on_ref = cv.p + m * depth;
    const std::uint32_t id = static_cast<std::uint32_t>(ref_face) << 24 | static_cast<std::uint32_t>(inc_face) << 16 |
                             cv.edges << 8 | cv.planes;
    pts.push_back(ref_is_a ? make_point(on_ref, cv.p, depth, id) : make_point(cv.p, on_ref, depth, id));
  }
  return reduce(pts, sat.normal, ContactMethod::kBoxBoxSat);
}

ContactManifold convex_plane_manifold(const ConvexShape& a, const Pose& pa, const HalfSpace& plane) {
  std::vector<Vec3> vertices;
  if (const Box* b = std::get_if<Box>(&a.geometry)) {
    for (int k = 0; k < 8; ++k)
      vertices.push_back({k & 1 ? b->half_extents.x : -b->half_extents.x, k & 2 ? b->half_extents.y : -b->half_extents.y,
                          k & 4 ? b->half_extents.z : -b->half_extents.z});
  } else if (const ConvexPolyhedron* p = std::get_if<ConvexPolyhedron>(&a.geometry)) {
    vertices = p->hull.vertices;
  } else {
    const PartContact g = convex_plane_contact(a, pa, plane);
    ContactManifold m;
    m.normal = plane.normal;
    m.method = ContactMethod::kPlane;
    if (g.touching) m.points[m.count++] = make_point(g.point_a, g.point_b, g.delta_n, 0);
    return m;
  }
  std::vector<ManifoldPoint> pts;
  for (std::size_t k = 0; k < vertices.size(); ++k) {
    const Vec3 x = pa.to_parent(vertices[k]);
    const double depth = plane.offset - dot(plane.normal, x);
    if (depth > 0) pts.push_back(make_point(x, x + plane.normal * depth, depth, static_cast<std::uint32_t>(k)));
  }
  return reduce(pts, plane.normal, ContactMethod::kPlane);
}

ContactManifold contact_manifold(const ConvexShape& a, const Pose& pa, const ConvexShape& b, const Pose& pb,
                                 ContactCache* warm) {
  const Box* ba = std::get_if<Box>(&a.geometry);
  const Box* bb = std::get_if<Box>(&b.geometry);
  if (ba && bb) {
    const BoxBoxSat sat = box_box_sat(ba->half_extents, pa, bb->half_extents, pb, warm ? warm->sat_axis : -1);
    if (warm) warm->sat_axis = sat.axis;
    return box_box_manifold(ba->half_extents, pa, bb->half_extents, pb, sat);
  }
  const PartContact g = narrow_phase(a, pa, b, pb, warm);
  ContactManifold m;
  m.normal = g.normal;
  m.method = g.method;
  if (g.touching) m.points[m.count++] = make_point(g.point_a, g.point_b, g.delta_n, 0);
  return m;
}

}  // namespace talus
