#include "talus/analysis/collapse_centre_of_mass.h"

namespace talus::collapse {

Vec3 centre_of_mass(const Snapshot& snapshot) {
  Vec3 sum;
  double mass = 0;
  for (const ParticleRecord& p : snapshot.particles) {
    if (p.fixed) continue;
    sum += p.mass * p.position;
    mass += p.mass;
  }
  return mass > 0 ? sum / mass : Vec3{};
}

CentreOfMassShift centre_of_mass_shift(const Snapshot& initial, const Snapshot& final) {
  CentreOfMassShift s;
  s.initial = centre_of_mass(initial);
  s.final = centre_of_mass(final);
  s.displacement = s.final - s.initial;
  s.dx_over_x0 = s.initial.x != 0 ? s.displacement.x / s.initial.x : 0.0;
  return s;
}

}  // namespace talus::collapse
