#pragma once
// A 3-vector of doubles: the engine's hot-path value type (Eigen is used off the hot path).
#include <cmath>
#include <type_traits>

namespace talus {

struct Vec3 {
  double x = 0, y = 0, z = 0;

  constexpr Vec3() = default;
  constexpr Vec3(double inX, double inY, double inZ) : x(inX), y(inY), z(inZ) {}

  // x, y, z are contiguous (static_assert below): indexing reads the member directly. The chain
  // of selects a runtime index otherwise compiles to cost 4 % of a cross pile's instructions.
  constexpr double operator[](int i) const {
    if (std::is_constant_evaluated()) return i == 0 ? x : (i == 1 ? y : z);
    return (&x)[i];
  }
  constexpr double& operator[](int i) {
    if (std::is_constant_evaluated()) return i == 0 ? x : (i == 1 ? y : z);
    return (&x)[i];
  }

  constexpr Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
  constexpr Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
  constexpr Vec3 operator-() const { return {-x, -y, -z}; }
  constexpr Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }
  constexpr Vec3 operator/(double s) const { return {x / s, y / s, z / s}; }
  constexpr Vec3& operator+=(const Vec3& o) { x += o.x; y += o.y; z += o.z; return *this; }
  constexpr Vec3& operator-=(const Vec3& o) { x -= o.x; y -= o.y; z -= o.z; return *this; }
  constexpr Vec3& operator*=(double s) { x *= s; y *= s; z *= s; return *this; }
  constexpr bool operator==(const Vec3&) const = default;
};
static_assert(std::is_standard_layout_v<Vec3> && sizeof(Vec3) == 3 * sizeof(double));

constexpr Vec3 operator*(double s, const Vec3& v) { return v * s; }
constexpr double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
constexpr double norm2(const Vec3& v) { return dot(v, v); }
inline double norm(const Vec3& v) { return std::sqrt(norm2(v)); }
constexpr Vec3 hadamard(const Vec3& a, const Vec3& b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }

// Unit vector of v, or zero when v is zero (callers treat a zero direction as "none").
inline Vec3 normalized_or_zero(const Vec3& v) {
  const double n = norm(v);
  return n > 0 ? v / n : Vec3{};
}

}  // namespace talus
