#pragma once
// Unit quaternions for rigid-body orientation (w + xi + yj + zk).
#include "talus/math/vec3.h"

namespace talus {

struct Quat {
  double w = 1, x = 0, y = 0, z = 0;

  constexpr Quat() = default;
  constexpr Quat(double inW, double inX, double inY, double inZ) : w(inW), x(inX), y(inY), z(inZ) {}

  static Quat from_axis_angle(const Vec3& axis, double angle) {
    const Vec3 u = normalized_or_zero(axis);
    const double s = std::sin(0.5 * angle);
    return {std::cos(0.5 * angle), u.x * s, u.y * s, u.z * s};
  }

  // The rotation taking the x, y and z axes to ex, ey and ez (orthonormal, right-handed): the
  // rotation matrix [ex ey ez] read by Shepperd's method, from its largest diagonal term.
  static Quat from_frame(const Vec3& ex, const Vec3& ey, const Vec3& ez) {
    const double trace = ex.x + ey.y + ez.z;
    Quat q;
    if (trace >= ex.x && trace >= ey.y && trace >= ez.z) {
      const double s = 2 * std::sqrt(1 + trace);
      q = {0.25 * s, (ey.z - ez.y) / s, (ez.x - ex.z) / s, (ex.y - ey.x) / s};
    } else if (ex.x >= ey.y && ex.x >= ez.z) {
      const double s = 2 * std::sqrt(1 + ex.x - ey.y - ez.z);
      q = {(ey.z - ez.y) / s, 0.25 * s, (ey.x + ex.y) / s, (ez.x + ex.z) / s};
    } else if (ey.y >= ez.z) {
      const double s = 2 * std::sqrt(1 - ex.x + ey.y - ez.z);
      q = {(ez.x - ex.z) / s, (ey.x + ex.y) / s, 0.25 * s, (ez.y + ey.z) / s};
    } else {
      const double s = 2 * std::sqrt(1 - ex.x - ey.y + ez.z);
      q = {(ex.y - ey.x) / s, (ez.x + ex.z) / s, (ez.y + ey.z) / s, 0.25 * s};
    }
    return q.normalized();
  }

  constexpr Vec3 vec() const { return {x, y, z}; }
  constexpr Quat conjugate() const { return {w, -x, -y, -z}; }
  constexpr bool operator==(const Quat&) const = default;

  constexpr Quat operator*(const Quat& o) const {
    return {w * o.w - x * o.x - y * o.y - z * o.z, w * o.x + x * o.w + y * o.z - z * o.y,
            w * o.y - x * o.z + y * o.w + z * o.x, w * o.z + x * o.y - y * o.x + z * o.w};
  }

  // Rotates v from the body frame to the world frame: q v q^-1.
  constexpr Vec3 rotate(const Vec3& v) const {
    const Vec3 u = vec();
    const Vec3 t = 2.0 * cross(u, v);
    return v + w * t + cross(u, t);
  }
  // Rotates v from the world frame to the body frame: q^-1 v q.
  constexpr Vec3 rotate_inverse(const Vec3& v) const { return conjugate().rotate(v); }

  Quat normalized() const {
    const double n = std::sqrt(w * w + x * x + y * y + z * z);
    return {w / n, x / n, y / n, z / n};
  }
};

}  // namespace talus
