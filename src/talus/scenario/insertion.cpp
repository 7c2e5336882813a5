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
  // Clamped before the cast: a point far outside the box would not fit an int.
  return static_cast<int>(std::clamp(std::floor((x - lo_[a]) / w), 0.0, count_[a] - 1.0));
}

long SphereOverlapIndex::key(int a, int b, int c) const {
  return (static_cast<long>(a) * count_[1] + b) * count_[2] + c;
}

bool SphereOverlapIndex::touches(const PlacedSphere& s, std::uint32_t id) const {
  Vec3 d = s.centre - spheres_[id].centre;
  for (int a = 0; a < 3; ++a)
    if (periodic_[a]) d[a] -= (hi_[a] - lo_[a]) * std::round(d[a] / (hi_[a] - lo_[a]));
  const double r = s.radius + spheres_[id].radius;
  return norm2(d) < r * r;
}

bool SphereOverlapIndex::overlaps(const PlacedSphere& s) const {
  // The cells within the largest possible centre distance, each visited once: `first[a]` and on
  // for `span[a]` cells, wrapped on periodic axes, cut at the box on the others.
  int first[3], span[3];
  double window = 1;
  for (int a = 0; a < 3; ++a) {
    const int c = cell_index(s.centre[a], a);
    // Bounded before the cast: a sphere may be far larger than the cells.
    const double cells = std::ceil((s.radius + max_radius_) / ((hi_[a] - lo_[a]) / count_[a]));
    const int reach = static_cast<int>(std::clamp(cells, 1.0, static_cast<double>(count_[a])));
    if (periodic_[a] && 2 * reach + 1 >= count_[a]) {
      first[a] = 0;
      span[a] = count_[a];
    } else if (periodic_[a]) {
      first[a] = c - reach;
      span[a] = 2 * reach + 1;
    } else {
      first[a] = std::max(0, c - reach);
      span[a] = std::min(count_[a] - 1, c + reach) - first[a] + 1;
    }
    window *= span[a];
  }
  // A sphere much larger than the cells would visit more cells than there are spheres (up to
  // the whole grid, at every rejected placement): then the spheres themselves are fewer.
  if (window > static_cast<double>(spheres_.size())) {
    for (std::uint32_t id = 0; id < spheres_.size(); ++id)
      if (touches(s, id)) return true;
    return false;
  }
  auto wrap = [&](int k, int a) { return (k % count_[a] + count_[a]) % count_[a]; };
  for (int i = 0; i < span[0]; ++i)
    for (int j = 0; j < span[1]; ++j)
      for (int l = 0; l < span[2]; ++l)
        for (std::uint32_t id : cells_[key(wrap(first[0] + i, 0), wrap(first[1] + j, 1), wrap(first[2] + l, 2))])
          if (touches(s, id)) return true;
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
                      std::size_t max_attempts, const std::function<bool(const PlacedSphere&)>& blocked) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double top = size.z;
  std::size_t placed = 0, failures = 0;
  while (placed < count) {
    const double r = radius(rng);
    const PlacedSphere s{{lo.x + size.x * unit(rng), lo.y + size.y * unit(rng), lo.z + top * unit(rng)}, r};
    if (index.overlaps(s) || (blocked && blocked(s))) {
      top += growth;
      // Rejections in a row are counted whatever the growth: one too small to move the top
      // would never bring it to max_top.
      if (top > max_top || ++failures > max_attempts)
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
