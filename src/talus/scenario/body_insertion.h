#pragma once
// Dense random placement of rigid bodies (copies of one composite shape) with exact overlap
// tests between their convex parts, rather than between bounding spheres: the long thin
// crosses of Huet et al. 2021 fill about 0.7 % of their bounding sphere, so sphere-based
// insertion leaves a cloud ten times taller than the pile it settles into, and a tall cloud
// costs a long fall to simulate.
//
//   insert_bodies(shape, count, lo, hi, growth, rng, clearance)
// Each attempt draws a centre uniformly in [lo, (hi.x, hi.y, top)] and a uniform random
// orientation; it is kept when the body's parts stay inside [lo, hi] (sides and floor) and
// no part comes within `clearance` of a part of a body already placed. Every rejected attempt
// raises `top` (starting at hi.z) by `growth`.
#include <cstddef>
#include <random>
#include <vector>

#include "talus/shape/composite_shape.h"

namespace talus {

struct PlacedBody {
  Vec3 position;    ///< body origin (m)
  Quat orientation;
};

std::vector<PlacedBody> insert_bodies(const CompositeShape& shape, std::size_t count, const Vec3& lo, const Vec3& hi,
                                      double growth, std::mt19937_64& rng, double clearance = 0);

// True when two placed copies of the shape overlap (parts closer than `clearance`): boxes by
// the separating axis test on the sharp boxes grown by clearance / 2, other parts by the
// narrow phase.
bool bodies_overlap(const CompositeShape& shape, const PlacedBody& a, const PlacedBody& b, double clearance = 0);

}  // namespace talus
