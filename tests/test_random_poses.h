#pragma once
// A cross arm, and random orientations and directions, for the box-pair tests: uniform on the rotation group
// (a normalised 4-d Gaussian) and on the sphere.
#include <random>

#include "talus/math/quat.h"
#include "talus/math/vec3.h"

namespace talus::testing {

inline const Vec3 kArm{13.5e-3, 1e-3, 1.5e-3};  // a Huet cross arm's half extents (m)

inline Quat random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0, 1);
  return Quat{n(rng), n(rng), n(rng), n(rng)}.normalized();
}

inline Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0, 1);
  return normalized_or_zero(Vec3{n(rng), n(rng), n(rng)});
}

}  // namespace talus::testing
