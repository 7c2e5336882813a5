#include "talus/analysis/collapse_contacts.h"

#include <algorithm>
#include <cstdint>
#include <unordered_set>

namespace talus::collapse {
namespace {

bool has(const std::vector<int>& list, int wall) {
  return std::find(list.begin(), list.end(), wall) != list.end();
}

std::uint64_t pair_key(int a, int b) {
  const auto lo = static_cast<std::uint32_t>(std::min(a, b));
  const auto hi = static_cast<std::uint32_t>(std::max(a, b));
  return (static_cast<std::uint64_t>(lo) << 32) | hi;
}

bool valid(const Snapshot& s, int k) { return k >= 0 && static_cast<std::size_t>(k) < s.particles.size(); }

}  // namespace

bool Region::contains(const Vec3& p) const {
  return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y && p.z >= min.z && p.z <= max.z;
}

TableThreeRegions table_three_regions(double initial_length, double initial_height) {
  TableThreeRegions r;
  r.near_gate.min.x = 0.5 * initial_length;
  r.near_gate_top.min.x = 0.5 * initial_length;
  r.near_gate_top.min.z = 0.5 * initial_height;
  return r;
}

ContactStatistics contact_statistics(const Snapshot& snapshot, const WallRoles& roles, const Region& region) {
  ContactStatistics st;
  const auto inside = [&](int k) {
    return valid(snapshot, k) && !snapshot.particles[k].fixed && region.contains(snapshot.particles[k].position);
  };
  for (std::size_t k = 0; k < snapshot.particles.size(); ++k) st.particles += inside(static_cast<int>(k)) ? 1 : 0;

  std::unordered_set<std::uint64_t> pairs;
  for (const ContactRecord& c : snapshot.contacts) {
    if (c.j < 0) {
      if (!region.contains(c.point)) continue;
      if (has(roles.ground, c.wall)) ++st.ground;
      else if (has(roles.side, c.wall)) ++st.side;
      else if (has(roles.gate, c.wall)) ++st.gate;
      continue;
    }
    // Each end inside the region gains this point and, at the pair's first point, a neighbour.
    const int ends = (inside(c.i) ? 1 : 0) + (inside(c.j) ? 1 : 0);
    st.contact_points += ends;
    if (pairs.insert(pair_key(c.i, c.j)).second) st.neighbours += ends;
  }
  if (st.particles > 0) {
    st.coordination = static_cast<double>(st.neighbours) / st.particles;
    st.coordination_points = static_cast<double>(st.contact_points) / st.particles;
  }
  return st;
}

WallLoadShares wall_load_shares(const Snapshot& snapshot, const WallRoles& roles) {
  const double g = norm(snapshot.gravity);
  const Vec3 up = g > 0 ? -snapshot.gravity / g : Vec3{0, 0, 1};
  double weight = 0;
  for (const ParticleRecord& p : snapshot.particles) weight += p.fixed ? 0.0 : p.mass * g;
  WallLoadShares s;
  if (!(weight > 0)) return s;
  for (const ContactRecord& c : snapshot.contacts) {
    if (c.j >= 0) continue;
    const double lift = dot(c.force, up) / weight;
    if (has(roles.ground, c.wall)) s.ground += lift;
    else if (has(roles.side, c.wall)) s.side += lift;
    else if (has(roles.gate, c.wall)) s.gate += lift;
  }
  return s;
}

}  // namespace talus::collapse
