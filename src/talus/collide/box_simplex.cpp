#include "talus/collide/box_simplex.h"

namespace talus {
namespace {

constexpr int kCountBits = 3, kPairBits = 6;

// Which corner a point of the box is: bit k set when its local coordinate k is positive.
std::uint32_t corner_id(const Vec3& world, const Pose& pose) {
  const Vec3 local = pose.to_child(world);
  return (local.x >= 0 ? 1u : 0u) | (local.y >= 0 ? 2u : 0u) | (local.z >= 0 ? 4u : 0u);
}

Vec3 corner(const Box& box, std::uint32_t id, const Pose& pose) {
  const Vec3& h = box.half_extents;
  return pose.to_parent({id & 1u ? h.x : -h.x, id & 2u ? h.y : -h.y, id & 4u ? h.z : -h.z});
}

}  // namespace

std::uint32_t box_simplex_code(const Simplex& s, const Pose& pose_a, const Pose& pose_b) {
  std::uint32_t code = static_cast<std::uint32_t>(s.size);
  for (int k = 0; k < s.size; ++k) {
    const std::uint32_t pair = corner_id(s.p[k].a, pose_a) | corner_id(s.p[k].b, pose_b) << 3;
    code |= pair << (kCountBits + kPairBits * k);
  }
  return code;
}

Simplex box_simplex(std::uint32_t code, const Box& a, const Pose& pose_a, const Box& b, const Pose& pose_b) {
  Simplex s;
  const int size = static_cast<int>(code & ((1u << kCountBits) - 1));
  for (int k = 0; k < size && k < 4; ++k) {
    const std::uint32_t pair = code >> (kCountBits + kPairBits * k);
    const Vec3 pa = corner(a, pair & 7u, pose_a), pb = corner(b, pair >> 3 & 7u, pose_b);
    s.push({pa - pb, pa, pb});
  }
  return s;
}

}  // namespace talus
