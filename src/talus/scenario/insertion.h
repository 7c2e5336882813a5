#pragma once
// Random non-overlapping placement of spheres.
#include <cstdint>
#include <functional>
#include <random>
#include <vector>

#include "talus/math/vec3.h"

namespace talus {

struct PlacedSphere {
  Vec3 centre;    ///< m
  double radius;  ///< m
};

// Overlap queries against a growing set of spheres, on a uniform hash grid (periodic along
// the flagged axes of the box [lo, hi]).
class SphereOverlapIndex {
 public:
  SphereOverlapIndex(const Vec3& lo, const Vec3& hi, const bool periodic[3], double cell);
  bool overlaps(const PlacedSphere& s) const;
  void insert(const PlacedSphere& s);
  const std::vector<PlacedSphere>& spheres() const { return spheres_; }

 private:
  long key(int a, int b, int c) const;
  bool touches(const PlacedSphere& s, std::uint32_t id) const;  ///< overlap with sphere `id`, periodic images included
  int cell_index(double x, int axis) const;
  Vec3 lo_, hi_;
  bool periodic_[3];
  double cell_;
  double max_radius_ = 0;
  int count_[3];
  std::vector<std::vector<std::uint32_t>> cells_;
  std::vector<PlacedSphere> spheres_;
};

// Weinhart et al. 2012, Sect. 5: place `count` spheres at uniform random positions in the box
// [lo, lo + (size.x, size.y, I)] starting with I = size.z; each rejected attempt (overlapping
// a placed sphere, or one `blocked` refuses, e.g. cutting into a wall) raises the top I by
// `growth`. Returns the final I. Throws std::runtime_error when I would exceed `max_top`, or
// after `max_attempts` rejections in a row.
double insert_growing(SphereOverlapIndex& index, std::size_t count, const Vec3& lo, const Vec3& size,
                      double growth, const std::function<double(std::mt19937_64&)>& radius, std::mt19937_64& rng,
                      double max_top = 1e300, std::size_t max_attempts = 100000,
                      const std::function<bool(const PlacedSphere&)>& blocked = {});

}  // namespace talus
