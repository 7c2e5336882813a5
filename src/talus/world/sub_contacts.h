#pragma once
// Contact points between the convex parts of two bodies (or a body and a wall), each with its
// own memory, keyed by (part of i, part of j, feature) so that history follows a contact point
// from step to step even as the manifold changes.
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "talus/math/vec3.h"

namespace talus {

// A contact point between two boxes as recycled points keep it (WorldSettings::manifold_recycle,
// box_pair_reuse.h): the deepest point of box i in box j, of box j in box i, and the normal (from
// j towards i), in the boxes' own frames as they stood when the point was last computed. Not
// carried over a rebuild: the part budgets that allow a recycle are cleared there.
struct PointAnchors {
  Vec3 deepest_i, deepest_j, normal_in_i;
};

struct SubContact {
  std::uint16_t part_i = 0, part_j = 0;  ///< part indices in each body's composite
  std::uint32_t feature = 0;             ///< manifold feature id; one point per part pair: GJK's simplex (box_simplex.h)
  Vec3 spring;                           ///< m, tangential memory delta_t
  Vec3 normal_prev;                      ///< previous normal (zero: new contact)
  Vec3 point;                            ///< m, contact point at the last step
  Vec3 force;                            ///< N, force on i at the last step
  double overlap = 0;                    ///< m
  double share = 1;                      ///< fraction of k_n and eta_n this point carries (1/points of its manifold)
  PointAnchors anchors;                  ///< set only with WorldSettings::manifold_recycle

  // The key of a manifold's point (a single point per part pair is found by its parts alone).
  bool same_key(const SubContact& o) const { return part_i == o.part_i && part_j == o.part_j && feature == o.feature; }
};

using SubContactList = std::vector<SubContact>;

// The points seen from the other body: parts swapped, memories negated.
inline void reverse_points(std::span<SubContact> points) {
  for (SubContact& s : points) {
    std::swap(s.part_i, s.part_j);
    s.spring = -s.spring;
    s.normal_prev = -s.normal_prev;
    s.force = -s.force;
  }
}

}  // namespace talus
