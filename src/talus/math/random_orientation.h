#pragma once
// A rotation drawn uniformly on SO(3): a normalised 4D Gaussian is uniform on the unit
// quaternions' sphere.
#include <random>

#include "talus/math/quat.h"

namespace talus {

template <class Rng>
Quat random_orientation(Rng& rng) {
  std::normal_distribution<double> g(0, 1);
  return Quat{g(rng), g(rng), g(rng), g(rng)}.normalized();
}

}  // namespace talus
