#pragma once
// A box placed in the world with its axes as vectors: the form the box-box separating axis test
// and the clipping manifold read, built once per part per body pair instead of turning the
// quaternion into a matrix for every query.
#include <cstdint>

#include "talus/math/quat.h"
#include "talus/math/vec3.h"
#include "talus/shape/pose.h"

namespace talus {

struct OrientedBox {
  Vec3 centre;   ///< (m)
  Vec3 axis[3];  ///< unit box axes in the world (columns of the rotation matrix)
  Vec3 half;     ///< half extents along axis[k] (m)
};

// Columns of the rotation matrix of q: the body axes in the world frame.
inline void rotation_axes(const Quat& q, Vec3 axes[3]) {
  const double xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z, xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z,
               wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
  axes[0] = {1 - 2 * (yy + zz), 2 * (xy + wz), 2 * (xz - wy)};
  axes[1] = {2 * (xy - wz), 1 - 2 * (xx + zz), 2 * (yz + wx)};
  axes[2] = {2 * (xz + wy), 2 * (yz - wx), 1 - 2 * (xx + yy)};
}

// A placed box as GJK's support mapping: three dot products and no quaternion, the box's
// axes being already in the world frame. Ties (d normal to an axis) take the + corner, as
// support(Box) does in the box's own frame.
struct OrientedBoxSupport {
  const OrientedBox* box;
  Vec3 support(const Vec3& d) const {
    std::uint32_t corner;
    return support(d, &corner);
  }
  // The same, naming the corner: bit k set on the + side of axis k (box_simplex.h).
  Vec3 support(const Vec3& d, std::uint32_t* corner) const {
    const OrientedBox& b = *box;
    const bool x = dot(b.axis[0], d) >= 0, y = dot(b.axis[1], d) >= 0, z = dot(b.axis[2], d) >= 0;
    *corner = (x ? 1u : 0u) | (y ? 2u : 0u) | (z ? 4u : 0u);
    return b.centre + b.axis[0] * (x ? b.half.x : -b.half.x) + b.axis[1] * (y ? b.half.y : -b.half.y) +
           b.axis[2] * (z ? b.half.z : -b.half.z);
  }
  Vec3 centre() const { return box->centre; }
};

inline OrientedBox oriented_box(const Vec3& half, const Pose& pose) {
  OrientedBox b;
  b.centre = pose.position;
  rotation_axes(pose.orientation, b.axis);
  b.half = half;
  return b;
}

}  // namespace talus
