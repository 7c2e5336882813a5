#pragma once
// Pose: a rigid placement (translation + rotation) of a frame in a parent frame.
// to_parent(p) maps a point from the child frame to the parent frame; to_child inverts it.
// Used for part-in-body poses (composites) and body-in-world poses (narrow phase).
#include "talus/math/quat.h"
#include "talus/math/vec3.h"

namespace talus {

struct Pose {
  Vec3 position;     ///< origin of the child frame in the parent frame (m)
  Quat orientation;  ///< rotation child -> parent (unit)

  constexpr Vec3 to_parent(const Vec3& p) const { return position + orientation.rotate(p); }
  constexpr Vec3 to_child(const Vec3& p) const { return orientation.rotate_inverse(p - position); }
  // Pose of a grandchild frame: this * inner (inner is given in this pose's child frame).
  constexpr Pose operator*(const Pose& inner) const {
    return {to_parent(inner.position), orientation * inner.orientation};
  }
};

}  // namespace talus
