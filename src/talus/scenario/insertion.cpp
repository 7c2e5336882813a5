#include "talus/scenario/insertion.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace talus {

SphereOverlapIndex::SphereOverlapIndex(const Vec3& lo, const Vec3& hi, const bool periodic[3], double cell)
    : lo_(lo), hi_(hi), cell_(cell) {
  // A large box of small spheres would need more cells than spheres: widen the cells.
  for (;; cell *= 1.5) {
    double total = 1;
    for (int a = 0; a < 3; ++a) total *= std::max(1.0, std::floor((hi[a] - lo[a]) / cell));
    if (total <= (1 << 20)) break;
  }
  cell_ = cell;
  for (int a = 0; a < 3; ++a) {
    periodic_[a] = periodic[a];
    count_[a] = std::max(1, static_cast<int>(std::floor((hi[a] - lo[a]) / cell)));
  }
  cells_.resize(static_cast<std::size_t>(count_[0]) * count_[1] * count_[2]);
}

int SphereOverlapIndex::cell_index(double x, int a) const {
  const double w = (hi_[a] - lo_[a]) / count_[a];
  return std::clamp(static_cast<int>(std::floor((x - lo_[a]) / w)), 0, count_[a] - 1);
}

long SphereOverlapIndex::key(int a, int b, int c) const {
  return (static_cast<long>(a) * count_[1] + b) * count_[2] + c;
}

bool SphereOverlapIndex::overlaps(const PlacedSphere& s) const {
  int c[3];
  for (int a = 0; a < 3; ++a) c[a] = cell_index(s.centre[a], a);
  // Search as many cells out as the largest possible centre distance needs.
  int reach[3];
  for (int a = 0; a < 3; ++a)
    reach[a] = std::min(count_[a], std::max(1, static_cast<int>(std::ceil((s.radius + max_radius_) / ((hi_[a] - lo_[a]) / count_[a])))));
  for (int dx = -reach[0]; dx <= reach[0]; ++dx)
    for (int dy = -reach[1]; dy <= reach[1]; ++dy)
      for (int dz = -reach[2]; dz <= reach[2]; ++dz) {
        int k[3] = {c[0] + dx, c[1] + dy, c[2] + dz};
        bool skip = false;
        for (int a = 0; a < 3; ++a) {
          if (k[a] >= 0 && k[a] < count_[a]) continue;
          if (!periodic_[a]) { skip = true; break; }
          k[a] = (k[a] + count_[a]) % count_[a];
        }
        if (skip) continue;
        for (std::uint32_t id : cells_[key(k[0], k[1], k[2])]) {
          Vec3 d = s.centre - spheres_[id].centre;
          for (int a = 0; a < 3; ++a)
            if (periodic_[a]) d[a] -= (hi_[a] - lo_[a]) * std::round(d[a] / (hi_[a] - lo_[a]));
          const double r = s.radius + spheres_[id].radius;
          if (norm2(d) < r * r) return true;
        }
      }
  return false;
}

void SphereOverlapIndex::insert(const PlacedSphere& s) {
  cells_[key(cell_index(s.centre.x, 0), cell_index(s.centre.y, 1), cell_index(s.centre.z, 2))].push_back(
      static_cast<std::uint32_t>(spheres_.size()));
  spheres_.push_back(s);
  max_radius_ = std::max(max_radius_, s.radius);
}

double insert_growing(SphereOverlapIndex& index, std::size_t count, const Vec3& lo, const Vec3& size, double growth,
                      const std::function<double(std::mt19937_64&)>& radius, std::mt19937_64& rng, double max_top,
                      std::size_t max_attempts) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double top = size.z;
  std::size_t placed = 0, failures = 0;
  while (placed < count) {
    const double r = radius(rng);
    const PlacedSphere s{{lo.x + size.x * unit(rng), lo.y + size.y * unit(rng), lo.z + top * unit(rng)}, r};
    if (index.overlaps(s)) {
      top += growth;
      if (top > max_top || (growth == 0 && ++failures > max_attempts))
        throw std::runtime_error("insertion region full after " + std::to_string(placed) + " of " +
                                 std::to_string(count) + " particles");
      continue;
    }
    failures = 0;
    index.insert(s);
    ++placed;
  }
  return top;
}

}  // namespace talus
