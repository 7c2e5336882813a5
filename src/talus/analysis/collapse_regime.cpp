#include "talus/analysis/collapse_regime.h"

#include <cmath>
#include <stdexcept>
#include <unordered_map>

namespace talus::collapse {

const char* to_string(Regime regime) {
  switch (regime) {
    case Regime::Stable: return "stable";
    case Regime::Fractured: return "fractured";
    case Regime::Collapsed: return "collapsed";
  }
  return "unknown";
}

int count_displaced(const Snapshot& initial, const Snapshot& final, double distance, int* matched) {
  std::unordered_map<std::uint32_t, Vec3> start;
  start.reserve(initial.particles.size());
  for (const ParticleRecord& p : initial.particles) {
    if (!p.fixed) start.emplace(p.id, p.position);
  }
  int moved = 0, both = 0;
  for (const ParticleRecord& p : final.particles) {
    if (p.fixed) continue;
    const auto it = start.find(p.id);
    if (it == start.end()) continue;
    ++both;
    if (norm(p.position - it->second) > distance) ++moved;
  }
  if (matched) *matched = both;
  return moved;
}

RegimeReport classify_regime(const Snapshot& initial, const Snapshot& final, const RegimeInput& input,
                             const RegimeTolerances& tol) {
  const double d = input.particle_size;
  if (!(d > 0)) throw std::invalid_argument("classify_regime: particle_size must be positive");
  RegimeReport r;
  r.runout_excess = (input.runout - input.initial_length) / d;
  r.height_change = std::abs(input.final_height - input.initial_height) / d;
  int matched = 0;
  r.displaced = count_displaced(initial, final, tol.displacement * d, &matched);
  r.displaced_fraction = matched > 0 ? static_cast<double>(r.displaced) / matched : 0.0;

  const bool height_kept = r.height_change <= tol.height;
  const bool length_kept = r.runout_excess <= tol.runout;
  const bool nothing_moved = r.displaced_fraction <= tol.displaced_fraction;
  if (height_kept && length_kept && nothing_moved) r.regime = Regime::Stable;
  else if (height_kept) r.regime = Regime::Fractured;
  else r.regime = Regime::Collapsed;
  return r;
}

}  // namespace talus::collapse
