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
