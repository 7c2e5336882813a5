#include "talus/analysis/force_network.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace talus {

Vec3 branch_vector(const Snapshot& snapshot, int i, int j) {
  Vec3 b = snapshot.particles[j].position - snapshot.particles[i].position;
  for (int k = 0; k < 3; ++k) {
    if (!snapshot.periodic[k]) continue;
    const double length = snapshot.domain_max[k] - snapshot.domain_min[k];
    if (length > 0) b[k] -= length * std::round(b[k] / length);
  }
  return b;
}

std::vector<ForceSegment> force_network(const Snapshot& snapshot, PairPoints points) {
  std::vector<ForceSegment> segments;
  std::vector<Vec3> total;  // summed force per segment, for merged pairs
  std::unordered_map<std::uint64_t, std::size_t> slot;
  for (const ContactRecord& c : snapshot.contacts) {
    if (c.j < 0) continue;
    if (points == PairPoints::MergePerPair) {
      const auto lo = static_cast<std::uint32_t>(std::min(c.i, c.j));
      const auto hi = static_cast<std::uint32_t>(std::max(c.i, c.j));
      const std::uint64_t key = (static_cast<std::uint64_t>(lo) << 32) | hi;
      const auto [it, fresh] = slot.emplace(key, segments.size());
      if (!fresh) {
        // The force on the pair's first-listed particle: flip points listed the other way round.
        const ForceSegment& s = segments[it->second];
        total[it->second] += (c.i == s.i) ? c.force : -c.force;
        segments[it->second].points += 1;
        continue;
      }
    }
    const Vec3 from = snapshot.particles[c.i].position;
    segments.push_back({c.i, c.j, from, from + branch_vector(snapshot, c.i, c.j), norm(c.force), 1});
    total.push_back(c.force);
  }
  for (std::size_t k = 0; k < segments.size(); ++k) segments[k].force = norm(total[k]);
  return segments;
}

std::vector<double> contact_force_magnitudes(const Snapshot& snapshot, PairPoints points, bool include_walls) {
  std::vector<double> forces;
  for (const ForceSegment& s : force_network(snapshot, points)) forces.push_back(s.force);
  if (include_walls) {
    for (const ContactRecord& c : snapshot.contacts) {
      if (c.j < 0) forces.push_back(norm(c.force));
    }
  }
  return forces;
}

}  // namespace talus
