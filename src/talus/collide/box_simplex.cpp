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

struct HalfAxes {
  Vec3 centre, e[3];
  explicit HalfAxes(const OrientedBox& box)
      : centre(box.centre), e{box.axis[0] * box.half.x, box.axis[1] * box.half.y, box.axis[2] * box.half.z} {}
  Vec3 corner(std::uint32_t id) const {
    return centre + (id & 1u ? e[0] : -e[0]) + (id & 2u ? e[1] : -e[1]) + (id & 4u ? e[2] : -e[2]);
  }
};

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

std::uint32_t box_simplex_code(const Simplex& s) {
  std::uint32_t code = static_cast<std::uint32_t>(s.size);
  for (int k = 0; k < s.size; ++k) code |= (s.p[k].corners & 63u) << (kCountBits + kPairBits * k);
  return code;
}

Simplex box_simplex(std::uint32_t code, const OrientedBox& a, const OrientedBox& b) {
  // Each box's half-axes once: a corner is then its centre plus or minus each, the very sums
  // (and bits) of corner(), since a product's sign follows the factor's.
  const HalfAxes ea(a), eb(b);
  Simplex s;
  const int size = static_cast<int>(code & ((1u << kCountBits) - 1));
  for (int k = 0; k < size && k < 4; ++k) {
    const std::uint32_t pair = code >> (kCountBits + kPairBits * k) & 63u;
    const Vec3 pa = ea.corner(pair & 7u), pb = eb.corner(pair >> 3);
    s.push({pa - pb, pa, pb, pair});
  }
  return s;
}

}  // namespace talus
