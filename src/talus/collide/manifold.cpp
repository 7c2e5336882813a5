#include "talus/collide/manifold.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <vector>

namespace talus {
namespace {

ManifoldPoint make_point(const Vec3& on_a, const Vec3& on_b, double depth, std::uint32_t id) {
  return {depth, (on_a + on_b) * 0.5, on_a, on_b, id};
}

// Keeps at most 4 points: the deepest, the farthest from it, then the two that make the
// largest triangles on either side of that segment (a stable, area-spanning subset).
ContactManifold reduce(const ManifoldPoint* pts, std::size_t count, const Vec3& normal, ContactMethod method) {
  ContactManifold m;
  m.normal = normal;
  m.method = method;
  if (count <= 4) {
    for (std::size_t k = 0; k < count; ++k) m.points[m.count++] = pts[k];
    return m;
  }
  std::size_t i0 = 0, i1 = 0, i2 = 0, i3 = 0;
  for (std::size_t k = 1; k < count; ++k)
    if (pts[k].delta_n > pts[i0].delta_n) i0 = k;
  double best = -1;
  for (std::size_t k = 0; k < count; ++k)
    if (const double d = norm2(pts[k].point - pts[i0].point); d > best) best = d, i1 = k;
  const Vec3 e = pts[i1].point - pts[i0].point;
  double hi = 0, lo = 0;
  for (std::size_t k = 0; k < count; ++k) {
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

ContactManifold reduce(const std::vector<ManifoldPoint>& pts, const Vec3& normal, ContactMethod method) {
  return reduce(pts.data(), pts.size(), normal, method);
}

struct ClipVertex {
  Vec3 p;
  unsigned edges;   // incident-face edges the point lies on (bit per edge)
  unsigned planes;  // reference side planes it lies on (bit per plane)
};

// A quad clipped by 4 planes has at most 8 vertices.
constexpr int kMaxClip = 8;

// The single point of an edge-edge contact (or none).
ContactManifold edge_manifold(const OrientedBox& a, const OrientedBox& b, const BoxBoxSat& sat) {
  ContactManifold out;
  out.normal = sat.normal;
  out.method = ContactMethod::kBoxBoxSat;
  if (sat.separated || sat.axis < 6) return out;
  out.points[0] = box_box_edge_point(a, b, sat);
  out.count = 1;
  return out;
}

}  // namespace

// Every return is an unnamed value, built in the caller's slot: with a named manifold on one
// path and reduce()'s on another, the ~400 bytes were copied on return.
ContactManifold box_box_manifold(const OrientedBox& a, const OrientedBox& b, const BoxBoxSat& sat) {
  if (sat.separated || sat.axis < 0 || sat.axis >= 6) return edge_manifold(a, b, sat);
  // Reference face: on A (axis < 3) its outward normal is -normal; on B it is +normal.
  const bool ref_is_a = sat.axis < 3;
  const OrientedBox& ref = ref_is_a ? a : b;
  const OrientedBox& inc = ref_is_a ? b : a;
  const int rk = sat.axis % 3;
  const Vec3 m = ref_is_a ? -sat.normal : sat.normal;
  const int ref_face = 2 * rk + (dot(ref.axis[rk], m) > 0 ? 0 : 1) + (ref_is_a ? 0 : 6);
  const double ref_offset = dot(m, ref.centre) + ref.half[rk];

  // Incident face: the face of the other box most anti-parallel to m.
  int ik = 0;
  double most = 0;
  for (int k = 0; k < 3; ++k)
    if (const double c = std::abs(dot(inc.axis[k], m)); c > most) most = c, ik = k;
  const double sgn = dot(inc.axis[ik], m) > 0 ? -1.0 : 1.0;
  const int inc_face = 2 * ik + (sgn > 0 ? 0 : 1) + (ref_is_a ? 6 : 0);
  const int k1 = (ik + 1) % 3, k2 = (ik + 2) % 3;
  const Vec3 c = inc.centre + inc.axis[ik] * (sgn * inc.half[ik]);
  const Vec3 u = inc.axis[k1] * inc.half[k1], v = inc.axis[k2] * inc.half[k2];
  // Vertex q lies on edges q-1 and q (edge q joins vertex q to q+1).
  UninitializedArray<ClipVertex, 2 * kMaxClip> buffers;
  ClipVertex* poly = buffers.data();
  ClipVertex* next = buffers.data() + kMaxClip;
  poly[0] = {c + u + v, 0b1001u, 0};
  poly[1] = {c - u + v, 0b0011u, 0};
  poly[2] = {c - u - v, 0b0110u, 0};
  poly[3] = {c + u - v, 0b1100u, 0};
  int count = 4;

  // Side planes of the reference face: dot(s, x) <= w.
  int plane = 0;
  for (int k = 0; k < 3; ++k) {
    if (k == rk) continue;
    for (double s : {1.0, -1.0}) {
      const Vec3 n = ref.axis[k] * s;
      const double w = dot(n, ref.centre) + ref.half[k];
      // Each vertex's distance once (it is both ends of two edges). A plane that cuts nothing
      // leaves the polygon as it is: no copy (the same points as clipping it would give).
      double dist[kMaxClip];
      bool cuts = false;
      for (int q = 0; q < count; ++q) {
        dist[q] = dot(n, poly[q].p) - w;
        cuts = cuts || dist[q] > 0;
      }
      ++plane;
      if (!cuts) continue;
      int kept = 0;
      for (int q = 0; q < count; ++q) {
        const int r = q + 1 == count ? 0 : q + 1;  // no integer division in the hot loop
        const ClipVertex& pa = poly[q];
        const ClipVertex& pb = poly[r];
        const double da = dist[q], db = dist[r];
        if (da <= 0 && kept < kMaxClip) next[kept++] = pa;
        if (((da < 0 && db > 0) || (da > 0 && db < 0)) && kept < kMaxClip) {
          const double t = da / (da - db);
          next[kept++] = {pa.p + (pb.p - pa.p) * t, pa.edges & pb.edges, (pa.planes & pb.planes) | (1u << (plane - 1))};
        }
      }
      std::swap(poly, next);
      count = kept;
    }
  }

  UninitializedArray<ManifoldPoint, kMaxClip> pts;
  int n = 0;
  for (int q = 0; q < count; ++q) {
    const ClipVertex& cv = poly[q];
    const double depth = ref_offset - dot(m, cv.p);
    if (depth < 0) continue;
    const Vec3 on_ref = cv.p + m * depth;
    const std::uint32_t id = static_cast<std::uint32_t>(ref_face) << 24 | static_cast<std::uint32_t>(inc_face) << 16 |
                             cv.edges << 8 | cv.planes;
    pts[n++] = ref_is_a ? make_point(on_ref, cv.p, depth, id) : make_point(cv.p, on_ref, depth, id);
  }
  return reduce(pts.data(), static_cast<std::size_t>(n), sat.normal, ContactMethod::kBoxBoxSat);
}

bool box_box_refit(const OrientedBox& a, const OrientedBox& b, const std::uint32_t* ids, int count,
                   ContactManifold& out) {
  out.count = 0;
  out.method = ContactMethod::kBoxBoxSat;
  if (count < 1 || count > 4) return false;
  const std::uint32_t faces = ids[0] >> 16;
  const int ref_face = static_cast<int>(faces >> 8), inc_face = static_cast<int>(faces & 0xFF);
  if (ref_face >= 12 || inc_face >= 12 || (ref_face < 6) == (inc_face < 6)) return false;
  // The frames of box_box_manifold, from the two face ids instead of the SAT axis.
  const bool ref_is_a = ref_face < 6;
  const OrientedBox& ref = ref_is_a ? a : b;
  const OrientedBox& inc = ref_is_a ? b : a;
  const int rk = (ref_face % 6) / 2;
  const Vec3 m = ref_face % 2 == 0 ? ref.axis[rk] : -ref.axis[rk];
  const double ref_offset = dot(m, ref.centre) + ref.half[rk];
  const int ik = (inc_face % 6) / 2;
  const double sgn = inc_face % 2 == 0 ? 1.0 : -1.0;
  const int k1 = (ik + 1) % 3, k2 = (ik + 2) % 3;
  const Vec3 c = inc.centre + inc.axis[ik] * (sgn * inc.half[ik]);
  const Vec3 u = inc.axis[k1] * inc.half[k1], v = inc.axis[k2] * inc.half[k2];
  const Vec3 corner[4] = {c + u + v, c - u + v, c - u - v, c + u - v};
  // Side plane p (bit p of the mask): the clip's order, the two other axes of ref ascending, + then -.
  const auto side = [&](int p, Vec3& n, double& w) {
    int k = p / 2;
    if (k >= rk) ++k;
    n = ref.axis[k] * (p % 2 == 0 ? 1.0 : -1.0);
    w = dot(n, ref.centre) + ref.half[k];
  };
  out.normal = ref_is_a ? -m : m;
  for (int q = 0; q < count; ++q) {
    if (ids[q] >> 16 != faces) return false;
    const unsigned edges = (ids[q] >> 8) & 0xFFu, planes = ids[q] & 0xFFu;
    if (edges > 0xFu || planes > 0xFu) return false;
    Vec3 p;
    const int edge_bits = std::popcount(edges), plane_bits = std::popcount(planes);
    if (edge_bits == 2 && plane_bits == 0) {
      // Vertex q lies on edges q - 1 and q.
      const int vertex = edges == 0b1001u ? 0 : std::countr_zero(edges) + 1;
      if (edges != 0b1001u && edges != 3u << (vertex - 1)) return false;
      p = corner[vertex];
    } else if (edge_bits == 1 && plane_bits == 1) {
      const int e = std::countr_zero(edges);
      const Vec3& from = corner[e];
      const Vec3 along = corner[(e + 1) % 4] - from;
      Vec3 n;
      double w;
      side(std::countr_zero(planes), n, w);
      const double slope = dot(n, along);
      if (!(std::abs(slope) > 1e-12 * norm(along))) return false;
      p = from + along * ((w - dot(n, from)) / slope);
    } else if (edge_bits == 0 && plane_bits == 2) {
      // The line where two side planes meet, along the reference normal, through the incident face.
      Vec3 n1, n2;
      double w1, w2;
      const int p1 = std::countr_zero(planes);
      side(p1, n1, w1);
      side(std::countr_zero(planes & (planes - 1)), n2, w2);
      if (std::abs(dot(n1, n2)) > 0.5) return false;  // opposite planes do not meet
      const Vec3 on_line = ref.centre + n1 * (w1 - dot(n1, ref.centre)) + n2 * (w2 - dot(n2, ref.centre));
      const Vec3& face_normal = inc.axis[ik];
      const double slope = dot(face_normal, m);
      if (!(std::abs(slope) > 1e-6)) return false;
      p = on_line + m * (dot(face_normal, c - on_line) / slope);
    } else {
      return false;
    }
    const double depth = ref_offset - dot(m, p);
    if (depth < 0) continue;
    const Vec3 on_ref = p + m * depth;
    out.points[out.count++] = ref_is_a ? make_point(on_ref, p, depth, ids[q]) : make_point(p, on_ref, depth, ids[q]);
  }
  return true;
}

ContactManifold box_box_manifold(const Vec3& ha, const Pose& pa, const Vec3& hb, const Pose& pb, const BoxBoxSat& sat) {
  return box_box_manifold(oriented_box(ha, pa), oriented_box(hb, pb), sat);
}

ContactManifold convex_plane_manifold(const ConvexShape& a, const Pose& pa, const HalfSpace& plane,
                                      const OrientedBox* placed) {
  if (const Box* b = std::get_if<Box>(&a.geometry)) {
    // Eight corners on the stack: a wall contact of a box costs no heap.
    const Vec3 h = b->half_extents;
    // With the box's world axes, a corner's depth is the centre's minus three projections: a
    // corner above the plane by more than 1e-9 of the box size (rounding is 1e-16 of it) is
    // never turned by the quaternion. A box lying on a wall has four such corners.
    Vec3 reach;
    double centre_depth = 0, margin = -1;
    if (placed) {
      reach = {h.x * dot(plane.normal, placed->axis[0]), h.y * dot(plane.normal, placed->axis[1]),
               h.z * dot(plane.normal, placed->axis[2])};
      centre_depth = plane.offset - dot(plane.normal, placed->centre);
      margin = 1e-9 * (h.x + h.y + h.z);
    }
    UninitializedArray<ManifoldPoint, 8> pts;
    std::size_t n = 0;
    for (int k = 0; k < 8; ++k) {
      if (margin > 0 && centre_depth - ((k & 1 ? reach.x : -reach.x) + (k & 2 ? reach.y : -reach.y) +
                                        (k & 4 ? reach.z : -reach.z)) < -margin)
        continue;
      const Vec3 x = pa.to_parent({k & 1 ? h.x : -h.x, k & 2 ? h.y : -h.y, k & 4 ? h.z : -h.z});
      const double depth = plane.offset - dot(plane.normal, x);
      if (depth > 0) pts[n++] = make_point(x, x + plane.normal * depth, depth, static_cast<std::uint32_t>(k));
    }
    return reduce(pts.data(), n, plane.normal, ContactMethod::kPlane);
  }
  if (const ConvexPolyhedron* p = std::get_if<ConvexPolyhedron>(&a.geometry)) {
    std::vector<ManifoldPoint> pts;
    for (std::size_t k = 0; k < p->hull.vertices.size(); ++k) {
      const Vec3 x = pa.to_parent(p->hull.vertices[k]);
      const double depth = plane.offset - dot(plane.normal, x);
      if (depth > 0) pts.push_back(make_point(x, x + plane.normal * depth, depth, static_cast<std::uint32_t>(k)));
    }
    return reduce(pts, plane.normal, ContactMethod::kPlane);
  }
  const PartContact g = convex_plane_contact(a, pa, plane);
  ContactManifold m;
  m.normal = plane.normal;
  m.method = ContactMethod::kPlane;
  if (g.touching) m.points[m.count++] = make_point(g.point_a, g.point_b, g.delta_n, 0);
  return m;
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
