#pragma once
// A GJK simplex between two boxes, carried from one step to the next as vertex ids. Every support
// point of a box is one of its eight corners, so the simplex is a few pairs of corners: 27 bits
// (the count, then 3 + 3 sign bits per pair). Re-posed at the new step, those corners are points
// of A - B near the closest ones, and GJK started from them (Box2D's b2SimplexCache; GJK++'s
// warm start) usually stops at its first support query instead of rebuilding the simplex from a
// direction. Any code, even one made for other boxes, gives corners of these: a stale or
// swapped code costs iterations, never a wrong answer.
#include <cstdint>

#include "talus/collide/gjk_simplex.h"
#include "talus/collide/oriented_box.h"
#include "talus/shape/convex_shape.h"
#include "talus/shape/pose.h"

namespace talus {

// The ids of s's corner pairs (0: empty simplex). s must come from supports of two boxes posed
// at pose_a and pose_b.
std::uint32_t box_simplex_code(const Simplex& s, const Pose& pose_a, const Pose& pose_b);

// The simplex of `code`'s corner pairs at the boxes' current poses.
Simplex box_simplex(std::uint32_t code, const Box& a, const Pose& pose_a, const Box& b, const Pose& pose_b);

// The same for boxes placed as OrientedBox: corners from the world axes, no quaternion. The
// simplex of OrientedBoxSupport's queries names its corners (SupportPoint::corners), so its code
// is read off without looking at the points.
std::uint32_t box_simplex_code(const Simplex& s);
Simplex box_simplex(std::uint32_t code, const OrientedBox& a, const OrientedBox& b);

}  // namespace talus
