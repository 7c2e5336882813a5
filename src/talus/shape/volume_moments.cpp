#include "talus/shape/volume_moments.h"

#include <cmath>
#include <numbers>

namespace talus {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

Vector3d ev(const Vec3& v) { return {v.x, v.y, v.z}; }

// A rotation whose third column is the unit vector a.
Matrix3d frame_with_z(const Vec3& a) {
  const Vector3d z = ev(a).normalized();
  const Vector3d helper = std::abs(z.x()) < 0.9 ? Vector3d::UnitX() : Vector3d::UnitY();
  const Vector3d x = helper.cross(z).normalized();
  Matrix3d r;
  r.col(0) = x;
  r.col(1) = z.cross(x);
  r.col(2) = z;
  return r;
}

}  // namespace

VolumeMoments transformed(const VolumeMoments& m, const Pose& pose) {
  const Quat& q = pose.orientation;
  const Matrix3d R = Eigen::Quaterniond(q.w, q.x, q.y, q.z).toRotationMatrix();
  const Vector3d t = ev(pose.position);
  const Vector3d rf = R * m.first;
  VolumeMoments out;
  out.volume = m.volume;
  out.first = rf + m.volume * t;
  out.second = R * m.second * R.transpose() + rf * t.transpose() + t * rf.transpose() + m.volume * t * t.transpose();
  return out;
}

VolumeMoments box_moments(const Vec3& h, const Vec3& centre) {
  VolumeMoments m;
  m.volume = 8 * h.x * h.y * h.z;
  m.second.diagonal() << m.volume * h.x * h.x / 3, m.volume * h.y * h.y / 3, m.volume * h.z * h.z / 3;
  return transformed(m, Pose{centre, Quat{}});
}

VolumeMoments polyhedron_moments(const ConvexHull& h) {
  // Tetrahedra (origin, a, b, c): int x x^T = V/20 (sum p p^T + (sum p)(sum p)^T), origin included.
  VolumeMoments m;
  for (const auto& t : h.triangles) {
    const Vector3d a = ev(h.vertices[t[0]]), b = ev(h.vertices[t[1]]), c = ev(h.vertices[t[2]]);
    const double v = a.dot(b.cross(c)) / 6;
    const Vector3d s = a + b + c;
    m.volume += v;
    m.first += v * s / 4;
    m.second += v / 20 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
  }
  return m;
}

VolumeMoments moments(const ConvexGeometry& g) {
  VolumeMoments m;
  if (const auto* s = std::get_if<Sphere>(&g)) {
    m.volume = 4.0 / 3.0 * std::numbers::pi * std::pow(s->radius, 3);
    m.second = Matrix3d::Identity() * (m.volume * s->radius * s->radius / 5);
  } else if (const auto* b = std::get_if<Box>(&g)) {
    m = box_moments(b->half_extents, Vec3{});
  } else if (const auto* c = std::get_if<Cylinder>(&g)) {
    m.volume = 2 * std::numbers::pi * c->radius * c->radius * c->half_height;
    const double r2 = m.volume * c->radius * c->radius / 4;
    m.second.diagonal() << r2, r2, m.volume * c->half_height * c->half_height / 3;
  } else {
    m = polyhedron_moments(std::get<ConvexPolyhedron>(g).hull);
  }
  return m;
}

VolumeMoments spherical_cap_moments(double R, double h, const Vec3& centre, const Vec3& axis) {
  // Slices z in [d, R] (d = R - h) of area pi (R^2 - z^2) about the ball's centre, z along axis.
  const double d = R - h, pi = std::numbers::pi;
  auto upper_minus_lower = [&](auto&& antiderivative) { return antiderivative(R) - antiderivative(d); };
  VolumeMoments m;
  m.volume = upper_minus_lower([&](double z) { return pi * (R * R * z - z * z * z / 3); });
  const double first_z = upper_minus_lower([&](double z) { return pi * (R * R * z * z / 2 - z * z * z * z / 4); });
  const double zz = upper_minus_lower([&](double z) { return pi * (R * R * z * z * z / 3 - std::pow(z, 5) / 5); });
  // A disc of radius rho has int x^2 dA = pi rho^4 / 4, with rho^2 = R^2 - z^2.
  const double xx = upper_minus_lower(
      [&](double z) { return pi / 4 * (R * R * R * R * z - 2 * R * R * z * z * z / 3 + std::pow(z, 5) / 5); });
  m.first.z() = first_z;
  m.second.diagonal() << xx, xx, zz;
  const Matrix3d r = frame_with_z(axis);
  const Eigen::Quaterniond q(r);
  return transformed(m, Pose{centre, Quat{q.w(), q.x(), q.y(), q.z()}});
}

}  // namespace talus
