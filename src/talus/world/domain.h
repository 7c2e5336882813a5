#pragma once
// The simulation box and which of its axes are periodic.
#include <cmath>

#include "talus/math/vec3.h"

namespace talus {

struct Domain {
  Vec3 lo{0, 0, 0};                       ///< m
  Vec3 hi{1, 1, 1};                       ///< m
  bool periodic[3] = {false, false, false};

  double length(int axis) const { return hi[axis] - lo[axis]; }
  bool any_periodic() const { return periodic[0] || periodic[1] || periodic[2]; }
  // Wraps a coordinate into [lo, hi) along every periodic axis.
  Vec3 wrap(Vec3 x) const {
    for (int a = 0; a < 3; ++a) {
      if (!periodic[a]) continue;
      const double l = length(a);
      x[a] -= l * std::floor((x[a] - lo[a]) / l);
      if (x[a] >= hi[a]) x[a] = lo[a];  // guards the rounding of x = hi - tiny
    }
    return x;
  }
  // Shortest periodic image of a separation vector.
  Vec3 minimum_image(Vec3 d) const {
    for (int a = 0; a < 3; ++a)
      if (periodic[a]) d[a] -= length(a) * std::round(d[a] / length(a));
    return d;
  }
};

}  // namespace talus
