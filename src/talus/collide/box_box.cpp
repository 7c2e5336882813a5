#include "talus/collide/box_box.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "talus/collide/manifold.h"

namespace talus {
namespace {

// Closest points of segments p + s u and q + t v, |s| <= hp, |t| <= hq (Ericson Sec. 5.1.9).
void closest_segments(const Vec3& p, const Vec3& u, double hp, const Vec3& q, const Vec3& v, double hq, Vec3* cp,
                      Vec3* cq) {
  const Vec3 r = p - q;
  const double b = dot(u, v), c = dot(u, r), f = dot(v, r);
  const double denom = 1 - b * b;
  double s = denom > 1e-12 ? std::clamp((b * f - c) / denom, -hp, hp) : 0.0;
  double t = std::clamp(b * s + f, -hq, hq);
  s = std::clamp(b * t - c, -hp, hp);
  *cp = p + u * s;
  *cq = q + v * t;
}

// Edge axis k = 6 + 3 i + j is a_i x b_j; i1, i2 (j1, j2) are the two other axes of A (B) in
// cyclic order. A table: the divisions and remainders by 3 cost more than the overlap itself.
struct EdgeAxis {
  int i, j, i1, i2, j1, j2;
};
constexpr EdgeAxis kEdgeAxes[9] = {{0, 0, 1, 2, 1, 2}, {0, 1, 1, 2, 2, 0}, {0, 2, 1, 2, 0, 1},
                                   {1, 0, 2, 0, 1, 2}, {1, 1, 2, 0, 2, 0}, {1, 2, 2, 0, 0, 1},
                                   {2, 0, 0, 1, 1, 2}, {2, 1, 0, 1, 2, 0}, {2, 2, 0, 1, 0, 1}};
constexpr bool edge_table_is_cyclic() {
  for (int k = 0; k < 9; ++k) {
    const EdgeAxis& e = kEdgeAxes[k];
    if (e.i != k / 3 || e.j != k % 3 || e.i1 != (e.i + 1) % 3 || e.i2 != (e.i + 2) % 3 || e.j1 != (e.j + 1) % 3 ||
        e.j2 != (e.j + 2) % 3)
      return false;
  }
  return true;
}
static_assert(edge_table_is_cyclic());

// The 15 candidate axes of two boxes, in A's frame (Gottschalk et al. 1996).
struct SatAxes {
  const OrientedBox& a;
  const OrientedBox& b;
  double R[3][3], AbsR[3][3];
  Vec3 t;  // centre of B in A's frame

  SatAxes(const OrientedBox& a_, const OrientedBox& b_) : a(a_), b(b_) {
    // The small bias keeps nearly parallel edge pairs (degenerate cross products) from winning.
    constexpr double kBias = 1e-12;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) R[i][j] = dot(a.axis[i], b.axis[j]), AbsR[i][j] = std::abs(R[i][j]) + kBias;
    const Vec3 d = b.centre - a.centre;
    t = {dot(d, a.axis[0]), dot(d, a.axis[1]), dot(d, a.axis[2])};
  }

  // Overlap of the projections on axis k; false for a degenerate edge pair (parallel edges).
  bool overlap(int k, double* out) const {
    const Vec3& ha = a.half;
    const Vec3& hb = b.half;
    if (k < 3) {
      *out = ha[k] + hb[0] * AbsR[k][0] + hb[1] * AbsR[k][1] + hb[2] * AbsR[k][2] - std::abs(t[k]);
      return true;
    }
    if (k < 6) {
      const int j = k - 3;
      const double tj = t[0] * R[0][j] + t[1] * R[1][j] + t[2] * R[2][j];
      *out = ha[0] * AbsR[0][j] + ha[1] * AbsR[1][j] + ha[2] * AbsR[2][j] + hb[j] - std::abs(tj);
      return true;
    }
    const auto [i, j, i1, i2, j1, j2] = kEdgeAxes[k - 6];
    const double len = std::sqrt(R[i1][j] * R[i1][j] + R[i2][j] * R[i2][j]);
    if (!(len > 1e-6)) return false;
    const double ra = ha[i1] * AbsR[i2][j] + ha[i2] * AbsR[i1][j];
    const double rb = hb[j1] * AbsR[i][j2] + hb[j2] * AbsR[i][j1];
    const double tl = t[i2] * R[i1][j] - t[i1] * R[i2][j];
    *out = (ra + rb - std::abs(tl)) / len;
    return true;
  }

  // |a_i x b_j| of edge axis k >= 6, the length its overlap is divided by.
  double edge_length(int k) const {
    const auto [i, j, i1, i2, j1, j2] = kEdgeAxes[k - 6];
    return std::sqrt(R[i1][j] * R[i1][j] + R[i2][j] * R[i2][j]);
  }

  // World unit normal of axis k, from B to A.
  Vec3 normal(int k) const {
    if (k < 3) return t[k] > 0 ? -a.axis[k] : a.axis[k];
    if (k < 6) {
      const int j = k - 3;
      const double tj = t[0] * R[0][j] + t[1] * R[1][j] + t[2] * R[2][j];
      return tj > 0 ? -b.axis[j] : b.axis[j];
    }
    const auto [i, j, i1, i2, j1, j2] = kEdgeAxes[k - 6];
    const double tl = t[i2] * R[i1][j] - t[i1] * R[i2][j];
    const Vec3 L = normalized_or_zero(cross(a.axis[i], b.axis[j]));
    return tl > 0 ? -L : L;
  }

  BoxBoxSat result(int k, double depth, bool separated) const {
    BoxBoxSat r;
    r.separated = separated;
    r.depth = depth;
    r.normal = normal(k);
    r.axis = k;
    return r;
  }
};

// The overlap on an axis u is o(u) = min(h(u), h(-u)), h the support function of the Minkowski
// difference A - B. When every point of A moves by at most tau_A and of B by at most tau_B,
// h changes by at most tau_A + tau_B along a fixed u; when u turns by |du|, h changes by at most
// |du| max|p| over A - B, with max|p| <= |c_A - c_B| + |h_A| + |h_B|. A face normal turns by
// at most its box's rotation angle; an edge axis (a_i x b_j) / |a_i x b_j| by at most
// 2 (theta_A + theta_B) / |a_i x b_j|. With theta_A + theta_B <= turn_per_travel times the
// travel, each overlap changes by at most slope_k times the travel. box_box_sat keeps its warm
// axis w while o_w <= 1.005 min_k o_k, so it is sure to keep w while, for every other axis k,
// (o_w + slope_w T) / 1.005 <= o_k - slope_k T.
double reserve_from_overlaps(const OrientedBox& a, const OrientedBox& b, int axis, double turn_per_travel,
                             const double (&overlap)[15], const double (&length)[15]) {
  const double ha = norm(a.half), hb = norm(b.half);
  const double spread = norm(b.centre - a.centre) + ha + hb;
  const double rounding = 1e-9 * (ha + hb);  // the AbsR bias and round-off, far above both
  auto slope = [&](int k) { return 1 + spread * turn_per_travel * (k < 6 ? 1.0 : 2.0 / length[k]); };
  constexpr double kKeep = 1 / 1.005;
  const double kept = kKeep * overlap[axis], kept_slope = kKeep * slope(axis);
  double reserve = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 15; ++k) {
    if (k == axis) continue;
    const double margin = overlap[k] - kept - rounding * (1 + 1 / length[k]);
    reserve = std::min(reserve, margin / (slope(k) + kept_slope));
  }
  return std::max(reserve, 0.0);
}

// The 15-axis search; with `reserve`, a touching answer also gets its box_box_axis_reserve from
// the overlaps the search formed, so a full query does not set up the 15 axes a second time.
BoxBoxSat sat_search(const OrientedBox& a, const OrientedBox& b, int warm_axis, double turn_per_travel,
                     double* reserve) {
  const SatAxes s(a, b);
  const bool warm = warm_axis >= 0 && warm_axis < 15;
  // A gap lasts many steps: the axis that separated last time usually still does.
  if (BoxBoxSat r; warm && box_box_sat_on_axis(a, b, warm_axis, r) && r.separated) return r;
  // Most part pairs in a pile are apart: return at the first separating face axis. The gap
  // reported is then a lower bound of the distance, not the largest one.
  double overlap[15];
  bool valid[15];
  for (int k = 0; k < 6; ++k) {
    valid[k] = s.overlap(k, &overlap[k]);
    if (overlap[k] < 0) return s.result(k, overlap[k], true);
  }
  // Edge axes: overlap = num / len. The sign needs no square root, and neither does the
  // comparison with the best face unless the edge could win: touching pairs (the ones that get
  // here) are mostly face contacts, so most edge axes are settled without sqrt or division.
  static constexpr int next[3] = {1, 2, 0}, after[3] = {2, 0, 1};
  double num[15], len2[15];
  const Vec3& ha = a.half;
  const Vec3& hb = b.half;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int k = 6 + 3 * i + j, i1 = next[i], i2 = after[i], j1 = next[j], j2 = after[j];
      len2[k] = s.R[i1][j] * s.R[i1][j] + s.R[i2][j] * s.R[i2][j];
      const double ra = ha[i1] * s.AbsR[i2][j] + ha[i2] * s.AbsR[i1][j];
      const double rb = hb[j1] * s.AbsR[i][j2] + hb[j2] * s.AbsR[i][j1];
      const double tl = s.t[i2] * s.R[i1][j] - s.t[i1] * s.R[i2][j];
      num[k] = ra + rb - std::abs(tl);
      valid[k] = len2[k] > 1e-12;  // parallel edges: no axis
    }
  for (int k = 6; k < 15; ++k)
    if (valid[k] && num[k] < 0) return s.result(k, num[k] / std::sqrt(len2[k]), true);
  int best = 0;
  for (int k = 1; k < 6; ++k)
    if (overlap[k] < overlap[best]) best = k;
  // Face axes come first and edges must beat them by a relative margin: ties go to faces.
  const double edge_margin = 1e-9 * (norm(a.half) + norm(b.half));
  for (int k = 6; k < 15; ++k) {
    if (!valid[k]) continue;
    const double threshold = overlap[best] - edge_margin;
    // num / len < threshold, tested first as num^2 < threshold^2 len^2 with slack for rounding.
    if (k != warm_axis && (threshold <= 0 || num[k] * num[k] > threshold * threshold * len2[k] * (1 + 1e-9))) continue;
    overlap[k] = num[k] / std::sqrt(len2[k]);
    if (overlap[k] < threshold) best = k;
  }
  BoxBoxSat r;
  if (warm && valid[warm_axis] && overlap[warm_axis] <= overlap[best] * 1.005)
    box_box_sat_on_axis(a, b, warm_axis, r);
  else
    r = s.result(best, overlap[best], false);
  if (reserve) {
    double length[15] = {1, 1, 1, 1, 1, 1};
    for (int k = 6; k < 15; ++k) {
      if (!valid[k]) return r;  // parallel edges: an axis with no bound, *reserve stays 0
      length[k] = std::sqrt(len2[k]);
      overlap[k] = num[k] / length[k];
    }
    *reserve = reserve_from_overlaps(a, b, r.axis, turn_per_travel, overlap, length);
  }
  return r;
}

}  // namespace

BoxBoxSat box_box_sat(const OrientedBox& a, const OrientedBox& b, int warm_axis) {
  return sat_search(a, b, warm_axis, 0, nullptr);
}

BoxBoxSat box_box_sat_with_reserve(const OrientedBox& a, const OrientedBox& b, int warm_axis, double turn_per_travel,
                                   double* reserve) {
  *reserve = 0;
  return sat_search(a, b, warm_axis, turn_per_travel, reserve);
}

// Out of line: box_box_sat answers with this same code whenever its answer is the warm axis, so
// the two agree to the bit and a run gives the same result whether or not it reuses an axis (a
// restart forgets the budgets). Only the products the one axis needs are formed (4 to 8 of the
// 12 dot products of SatAxes), with SatAxes' expressions: a lasting contact runs this every step.
[[gnu::noinline]] bool box_box_sat_on_axis(const OrientedBox& a, const OrientedBox& b, int axis, BoxBoxSat& out) {
  constexpr double kBias = 1e-12;  // as SatAxes
  const Vec3 d = b.centre - a.centre;
  const Vec3& ha = a.half;
  const Vec3& hb = b.half;
  double o = 0;
  Vec3 normal;
  if (axis < 3) {
    const int k = axis;
    const double t = dot(d, a.axis[k]);
    o = ha[k] + hb[0] * (std::abs(dot(a.axis[k], b.axis[0])) + kBias) +
        hb[1] * (std::abs(dot(a.axis[k], b.axis[1])) + kBias) + hb[2] * (std::abs(dot(a.axis[k], b.axis[2])) + kBias) -
        std::abs(t);
    normal = t > 0 ? -a.axis[k] : a.axis[k];
  } else if (axis < 6) {
    const int j = axis - 3;
    double R[3];
    for (int i = 0; i < 3; ++i) R[i] = dot(a.axis[i], b.axis[j]);
    const double tj = dot(d, a.axis[0]) * R[0] + dot(d, a.axis[1]) * R[1] + dot(d, a.axis[2]) * R[2];
    o = ha[0] * (std::abs(R[0]) + kBias) + ha[1] * (std::abs(R[1]) + kBias) + ha[2] * (std::abs(R[2]) + kBias) + hb[j] -
        std::abs(tj);
    normal = tj > 0 ? -b.axis[j] : b.axis[j];
  } else {
    const auto [i, j, i1, i2, j1, j2] = kEdgeAxes[axis - 6];
    const double r1 = dot(a.axis[i1], b.axis[j]), r2 = dot(a.axis[i2], b.axis[j]);
    const double len = std::sqrt(r1 * r1 + r2 * r2);
    if (!(len > 1e-6)) return false;
    const double ra = ha[i1] * (std::abs(r2) + kBias) + ha[i2] * (std::abs(r1) + kBias);
    const double rb = hb[j1] * (std::abs(dot(a.axis[i], b.axis[j2])) + kBias) +
                      hb[j2] * (std::abs(dot(a.axis[i], b.axis[j1])) + kBias);
    const double tl = dot(d, a.axis[i2]) * r1 - dot(d, a.axis[i1]) * r2;
    o = (ra + rb - std::abs(tl)) / len;
    const Vec3 L = normalized_or_zero(cross(a.axis[i], b.axis[j]));
    normal = tl > 0 ? -L : L;
  }
  out.separated = o < 0;
  out.depth = o;
  out.normal = normal;
  out.axis = axis;
  return true;
}

// The same bound for a pair whose SAT ran elsewhere (the reserve's own set-up of the 15 axes).
double box_box_axis_reserve(const OrientedBox& a, const OrientedBox& b, int axis, double turn_per_travel) {
  const SatAxes s(a, b);
  double overlap[15], length[15];
  for (int k = 0; k < 15; ++k) {
    if (!s.overlap(k, &overlap[k])) return 0;  // parallel edges: an axis with no bound, re-test every step
    length[k] = k < 6 ? 1.0 : s.edge_length(k);
  }
  return reserve_from_overlaps(a, b, axis, turn_per_travel, overlap, length);
}

BoxBoxSat box_box_sat(const Vec3& ha, const Pose& pa, const Vec3& hb, const Pose& pb, int warm_axis) {
  return box_box_sat(oriented_box(ha, pa), oriented_box(hb, pb), warm_axis);
}

void box_box_edge_points(const OrientedBox& a, const OrientedBox& b, const BoxBoxSat& sat, Vec3& point_a,
                         Vec3& point_b) {
  int i = 0, j = 0;
  if (sat.axis >= 6) i = kEdgeAxes[sat.axis - 6].i, j = kEdgeAxes[sat.axis - 6].j;
  Vec3 ea = a.centre, eb = b.centre;
  for (int k = 0; k < 3; ++k) {
    if (k != i || sat.axis < 6) ea += a.axis[k] * (dot(a.axis[k], -sat.normal) >= 0 ? a.half[k] : -a.half[k]);
    if (k != j || sat.axis < 6) eb += b.axis[k] * (dot(b.axis[k], sat.normal) >= 0 ? b.half[k] : -b.half[k]);
  }
  if (sat.axis >= 6) {
    closest_segments(ea, a.axis[i], a.half[i], eb, b.axis[j], b.half[j], &point_a, &point_b);
  } else {
    point_a = ea;
    point_b = eb;
  }
}

PartContact box_box_contact(const OrientedBox& a, const OrientedBox& b, ContactCache* warm) {
  const BoxBoxSat sat = box_box_sat(a, b, warm ? warm->sat_axis : -1);
  if (warm) warm->sat_axis = sat.axis;
  PartContact g;
  g.method = ContactMethod::kBoxBoxSat;
  g.normal = sat.normal;
  g.delta_n = sat.depth;
  if (sat.separated) return g;
  if (sat.axis < 6) {
    const ContactManifold m = box_box_manifold(a, b, sat);
    double deepest = 0;
    for (int k = 0; k < m.count; ++k) deepest = std::max(deepest, m.points[k].delta_n);
    const double tol = 1e-9 * (norm(a.half) + norm(b.half)) + 1e-6 * deepest;
    int n = 0;
    for (int k = 0; k < m.count; ++k)
      if (m.points[k].delta_n >= deepest - tol) {
        g.point_a += m.points[k].point_a;
        g.point_b += m.points[k].point_b;
        ++n;
      }
    if (n > 0) {
      g.point_a = g.point_a / n;
      g.point_b = g.point_b / n;
      g.delta_n = deepest;
      return finish_contact(g);
    }
  }
  // Edge pair (or an empty clip from rounding): closest points of the two supporting edges.
  box_box_edge_points(a, b, sat, g.point_a, g.point_b);
  return finish_contact(g);
}

PartContact box_box_contact(const Vec3& ha, const Pose& pa, const Vec3& hb, const Pose& pb, ContactCache* warm) {
  return box_box_contact(oriented_box(ha, pa), oriented_box(hb, pb), warm);
}

}  // namespace talus
