#pragma once
// Random non-overlapping placement of rigid bodies by their true shape. Placing crosses by
// their bounding spheres would fill a column at a few per cent solid fraction and make the
// pour take seconds of simulated fall; testing the convex parts themselves packs the initial
// cloud several times denser, so the pile settles from a low height.
#include <cstdint>
#include <random>
#include <unordered_map>
#include <vector>

#include "talus/shape/composite_shape.h"

namespace talus {

struct PlacedBody {
  Vec3 position;                         ///< m, centre of mass
  Quat orientation;                      ///< body to world
  const CompositeShape* shape = nullptr; ///< parts in the body frame; nullptr: a sphere
  double radius = 0;                     ///< m, bounding radius (the radius of a sphere)
};

// Whether two bodies come closer than `clearance` (m), part by part.
bool bodies_overlap(const PlacedBody& a, const PlacedBody& b, double clearance);

// World box of a body's contact shape.
Aabb body_aabb(const PlacedBody& body);

// Overlap queries against a growing set of bodies, on a hash grid of cells of twice the
// largest bounding radius.
class BodyOverlapIndex {
 public:
  explicit BodyOverlapIndex(double max_radius);
  bool overlaps(const PlacedBody& body, double clearance = 0) const;
  void insert(const PlacedBody& body);
  const std::vector<PlacedBody>& bodies() const { return bodies_; }

 private:
  std::int64_t key(const Vec3& x) const;
  double cell_;
  std::unordered_map<std::int64_t, std::vector<std::uint32_t>> cells_;
  std::vector<PlacedBody> bodies_;
};

// Weinhart et al. 2012, Sect. 5, for bodies of any shape: copies of `prototype` at uniform
// random positions and orientations whose whole shape lies in [lo, lo + (size.x, size.y, I)],
// I starting at size.z and growing by `growth` at each rejection for overlap. Returns the
// placed bodies; throws std::runtime_error when I would pass max_top, or after `max_attempts`
// rejections in a row.
std::vector<PlacedBody> insert_bodies_growing(BodyOverlapIndex& index, const PlacedBody& prototype, std::size_t count,
                                              const Vec3& lo, const Vec3& size, double growth, double clearance,
                                              std::mt19937_64& rng, double max_top, std::size_t max_attempts = 100000);

}  // namespace talus
