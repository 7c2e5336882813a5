#pragma once
// Walls: planes, optionally bounded to a rectangle, fixed or moving with a prescribed motion.
#include <string>

#include "talus/math/vec3.h"

namespace talus {

// Prescribed rigid translation of a wall.
struct WallMotion {
  enum class Kind {
    fixed,
    removed,        ///< the wall disappears at `start_time` (instant gate removal)
    accelerated,    ///< from rest at `start_time`, constant acceleration up to `top_speed`, along `direction`
  };
  Kind kind = Kind::fixed;
  double start_time = 0;    ///< s
  Vec3 direction{0, 0, 1};  ///< unit
  double acceleration = 0;  ///< m/s^2 (the gate of Huet et al. 2021, Sec. III A: 43 m/s^2)
  double top_speed = 0;     ///< m/s (3 m/s for that gate)

  double speed(double t) const;          ///< m/s at time t
  double displacement(double t) const;   ///< m travelled by time t
};

struct Wall {
  std::string name;
  Vec3 origin;          ///< m, a point of the plane at t = 0 (the rectangle's centre when bounded)
  Vec3 normal{0, 0, 1}; ///< unit, pointing into the region where particles live
  int material = 0;     ///< wall material index, for the contact parameter table
  // A bounded wall acts only where the particle's projection falls inside the rectangle
  // origin + a u + b v, |a| <= half_extent_u, |b| <= half_extent_v, and only on particles whose
  // centre is in front of it: a thin plate, so what passed under a rising gate is left alone.
  bool bounded = false;
  Vec3 axis_u, axis_v;           ///< unit, in-plane axes of the rectangle
  double half_extent_u = 0, half_extent_v = 0;  ///< m
  WallMotion motion;

  bool active(double t) const {
    return !(motion.kind == WallMotion::Kind::removed && t >= motion.start_time);
  }
  // A moving rectangle slides in its plane too, uncovering and covering particles: its contact
  // list holds every particle near its plane, and only its motion along the normal uses up the
  // neighbour-list skin (WallContactList::build, World::needs_rebuild).
  bool moves() const { return motion.kind == WallMotion::Kind::accelerated; }
  Vec3 origin_at(double t) const { return origin + motion.direction * motion.displacement(t); }
  Vec3 velocity_at(double t) const { return motion.direction * motion.speed(t); }
};

}  // namespace talus
