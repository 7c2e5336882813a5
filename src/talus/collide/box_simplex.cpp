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

Vec3 corner(const OrientedBox& box, std::uint32_t id) {
  return box.centre + box.axis[0] * (id & 1u ? box.half.x : -box.half.x) +
         box.axis[1] * (id & 2u ? box.half.y : -box.half.y) + box.axis[2] * (id & 4u ? box.half.z : -box.half.z);
}

template <class IdA, class IdB>
std::uint32_t code_of(const Simplex& s, IdA id_a, IdB id_b) {
  std::uint32_t code = static_cast<std::uint32_t>(s.size);
  for (int k = 0; k < s.size; ++k) {
    const std::uint32_t pair = id_a(s.p[k].a) | id_b(s.p[k].b) << 3;
    code |= pair << (kCountBits + kPairBits * k);
  }
  return code;
}

template <class CornerA, class CornerB>
Simplex simplex_of(std::uint32_t code, CornerA corner_a, CornerB corner_b) {
  Simplex s;
  const int size = static_cast<int>(code & ((1u << kCountBits) - 1));
  for (int k = 0; k < size && k < 4; ++k) {
    const std::uint32_t pair = code >> (kCountBits + kPairBits * k);
    const Vec3 pa = corner_a(pair & 7u), pb = corner_b(pair >> 3 & 7u);
    s.push({pa - pb, pa, pb});
  }
  return s;
}

}  // namespace

std::uint32_t box_simplex_code(const Simplex& s, const Pose& pose_a, const Pose& pose_b) {
  return code_of(
      s, [&](const Vec3& x) { return corner_id(x, pose_a); }, [&](const Vec3& x) { return corner_id(x, pose_b); });
}

Simplex box_simplex(std::uint32_t code, const Box& a, const Pose& pose_a, const Box& b, const Pose& pose_b) {
  return simplex_of(
      code, [&](std::uint32_t id) { return corner(a, id, pose_a); }, [&](std::uint32_t id) { return corner(b, id, pose_b); });
}

std::uint32_t box_simplex_code(const Simplex& s) {
  std::uint32_t code = static_cast<std::uint32_t>(s.size);
  for (int k = 0; k < s.size; ++k) code |= (s.p[k].corners & 63u) << (kCountBits + kPairBits * k);
  return code;
}

Simplex box_simplex(std::uint32_t code, const OrientedBox& a, const OrientedBox& b) {
  Simplex s = simplex_of(
      code, [&](std::uint32_t id) { return corner(a, id); }, [&](std::uint32_t id) { return corner(b, id); });
  for (int k = 0; k < s.size; ++k) s.p[k].corners = code >> (kCountBits + kPairBits * k) & 63u;
  return s;
}

}  // namespace talus
