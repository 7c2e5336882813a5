#include "talus/collide/box_box.h"

#include <algorithm>
#include <cmath>

#include "talus/collide/manifold.h"

namespace talus {
namespace {

Vec3 axis_of(const Pose& p, int k) {
  Vec3 e;
  e[k] = 1;
  return p.orientation.rotate(e);
}

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

}  // namespace

// Columns of the rotation matrix of q: the body axes in the world frame.
void rotation_axes(const Quat& q, Vec3 axes[3]) {
  const double xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z, xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z,
               wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
  axes[0] = {1 - 2 * (yy + zz), 2 * (xy + wz), 2 * (xz - wy)};
  axes[1] = {2 * (xy - wz), 1 - 2 * (xx + zz), 2 * (yz + wx)};
  axes[2] = {2 * (xz + wy), 2 * (yz - wx), 1 - 2 * (xx + yy)};
}

BoxBoxSat box_box_sat(const Vec3& ha, const Pose& pa, const Vec3& hb, const Pose& pb, int warm_axis) {
  Vec3 A[3], B[3];
  rotation_axes(pa.orientation, A);
  rotation_axes(pb.orientation, B);
  double R[3][3], AbsR[3][3];
  // The small bias keeps nearly parallel edge pairs (degenerate cross products) from winning.
  constexpr double kBias = 1e-12;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) R[i][j] = dot(A[i], B[j]), AbsR[i][j] = std::abs(R[i][j]) + kBias;
  const Vec3 d = pb.position - pa.position;
  const Vec3 t{dot(d, A[0]), dot(d, A[1]), dot(d, A[2])};  // centre of B in A's frame

  double overlap[15];
  Vec3 normal[15];  // world, from B to A
  bool valid[15];
  // Most part pairs in a pile are apart: return at the first separating face axis. The gap
  // reported is then a lower bound of the distance, not the largest one.
  auto separated_by = [&](int k) {
    BoxBoxSat r;
    r.separated = true;
    r.depth = overlap[k];
    r.normal = normal[k];
    r.axis = k;
    return r;
  };
  for (int i = 0; i < 3; ++i) {
    const double rb = hb[0] * AbsR[i][0] + hb[1] * AbsR[i][1] + hb[2] * AbsR[i][2];
    overlap[i] = ha[i] + rb - std::abs(t[i]);
    normal[i] = t[i] > 0 ? -A[i] : A[i];
    valid[i] = true;
    if (overlap[i] < 0) return separated_by(i);
  }
  for (int j = 0; j < 3; ++j) {
    const double ra = ha[0] * AbsR[0][j] + ha[1] * AbsR[1][j] + ha[2] * AbsR[2][j];
    const double tj = t[0] * R[0][j] + t[1] * R[1][j] + t[2] * R[2][j];
    overlap[3 + j] = ra + hb[j] - std::abs(tj);
    normal[3 + j] = tj > 0 ? -B[j] : B[j];
    valid[3 + j] = true;
    if (overlap[3 + j] < 0) return separated_by(3 + j);
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int k = 6 + 3 * i + j, i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      const double len = std::sqrt(R[i1][j] * R[i1][j] + R[i2][j] * R[i2][j]);
      valid[k] = len > 1e-6;
      if (!valid[k]) continue;
      const double ra = ha[i1] * AbsR[i2][j] + ha[i2] * AbsR[i1][j];
      const double rb = hb[j1] * AbsR[i][j2] + hb[j2] * AbsR[i][j1];
      const double tl = t[i2] * R[i1][j] - t[i1] * R[i2][j];
      overlap[k] = (ra + rb - std::abs(tl)) / len;
      const Vec3 L = normalized_or_zero(cross(A[i], B[j]));
      normal[k] = tl > 0 ? -L : L;
    }

  BoxBoxSat r;
  int best = -1;
  for (int k = 0; k < 15; ++k) {
    if (!valid[k]) continue;
    if (overlap[k] < 0) {  // separating axis: report the largest gap as a distance lower bound
      if (!r.separated || overlap[k] < r.depth) r.depth = overlap[k], r.normal = normal[k], r.axis = k;
      r.separated = true;
    }
    // Face axes come first and edges must beat them by a relative margin: ties go to faces.
    const double margin = k < 6 ? 0.0 : 1e-9 * (norm(ha) + norm(hb));
    if (best < 0 || overlap[k] < overlap[best] - margin) best = k;
  }
  if (r.separated) return r;
  if (warm_axis >= 0 && warm_axis < 15 && valid[warm_axis] && overlap[warm_axis] <= overlap[best] * 1.005)
    best = warm_axis;
  r.depth = overlap[best];
  r.normal = normal[best];
  r.axis = best;
  return r;
}

PartContact box_box_contact(const Vec3& ha, const Pose& pa, const Vec3& hb, const Pose& pb, ContactCache* warm) {
  const BoxBoxSat sat = box_box_sat(ha, pa, hb, pb, warm ? warm->sat_axis : -1);
  if (warm) warm->sat_axis = sat.axis;
  PartContact g;
  g.method = ContactMethod::kBoxBoxSat;
  g.normal = sat.normal;
  g.delta_n = sat.depth;
  if (sat.separated) return g;
  if (sat.axis < 6) {
    const ContactManifold m = box_box_manifold(ha, pa, hb, pb, sat);
    double deepest = 0;
    for (int k = 0; k < m.count; ++k) deepest = std::max(deepest, m.points[k].delta_n);
    const double tol = 1e-9 * (norm(ha) + norm(hb)) + 1e-6 * deepest;
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
  int i = 0, j = 0;
  if (sat.axis >= 6) i = (sat.axis - 6) / 3, j = (sat.axis - 6) % 3;
  Vec3 ea = pa.position, eb = pb.position;
  for (int k = 0; k < 3; ++k) {
    const Vec3 a = axis_of(pa, k), b = axis_of(pb, k);
    if (k != i || sat.axis < 6) ea += a * (dot(a, -g.normal) >= 0 ? ha[k] : -ha[k]);
    if (k != j || sat.axis < 6) eb += b * (dot(b, g.normal) >= 0 ? hb[k] : -hb[k]);
  }
  if (sat.axis >= 6) {
    closest_segments(ea, axis_of(pa, i), ha[i], eb, axis_of(pb, j), hb[j], &g.point_a, &g.point_b);
  } else {
    g.point_a = ea;
    g.point_b = eb;
  }
  return finish_contact(g);
}

}  // namespace talus
