#include "talus/analysis/collapse_speed.h"

#include <cmath>
#include <stdexcept>

namespace talus::collapse {

MeanSpeeds mean_speeds(const Snapshot& snapshot) {
  MeanSpeeds m;
  int count = 0;
  for (const ParticleRecord& p : snapshot.particles) {
    if (p.fixed) continue;
    m.translational += norm(p.velocity);
    m.angular += norm(p.angular_velocity);
    ++count;
  }
  if (count > 0) {
    m.translational /= count;
    m.angular /= count;
  }
  return m;
}

double collapse_time_scale(double initial_height, double g) {
  if (!(initial_height > 0) || !(g > 0)) {
    throw std::invalid_argument("collapse_time_scale: needs a positive height and gravity");
  }
  return std::sqrt(initial_height / g);
}

ScaledSpeeds scaled_speeds(const Snapshot& snapshot, double initial_height, double t_gate) {
  const double g = norm(snapshot.gravity);
  const double tau = collapse_time_scale(initial_height, g);
  const MeanSpeeds m = mean_speeds(snapshot);
  return {(snapshot.time - t_gate) / tau, m.translational / std::sqrt(g * initial_height), m.angular * tau};
}

}  // namespace talus::collapse
