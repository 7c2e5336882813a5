#include "talus/world/wall.h"

#include <algorithm>

namespace talus {

double WallMotion::speed(double t) const {
  if (kind != Kind::accelerated || t <= start_time) return 0;
  return std::min(acceleration * (t - start_time), top_speed);
}

double WallMotion::displacement(double t) const {
  if (kind != Kind::accelerated || t <= start_time) return 0;
  const double tau = t - start_time;
  const double t_top = acceleration > 0 ? top_speed / acceleration : 0;
  if (tau <= t_top) return 0.5 * acceleration * tau * tau;
  return 0.5 * acceleration * t_top * t_top + top_speed * (tau - t_top);
}

}  // namespace talus
