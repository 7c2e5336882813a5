#pragma once
// Where coarse-grained fields are evaluated: a regular grid over the resolved directions
// (z for a depth profile, two axes for a plane, all three for a volume). Directions that are
// not resolved are averaged over the whole simulation box (Weinhart et al. 2012, Eq. 43).
#include <stdexcept>

#include "talus/math/vec3.h"

namespace talus {

struct CgGrid {
  bool resolved[3] = {false, false, false};
  int n[3] = {1, 1, 1};        ///< points per axis (1 on averaged axes)
  double lo[3] = {0, 0, 0};    ///< m, first point on each resolved axis
  double hi[3] = {0, 0, 0};    ///< m, last point on each resolved axis (inclusive)

  // A depth profile: nz points from z_lo to z_hi, averaged over x and y.
  static CgGrid depth(double z_lo, double z_hi, int nz) {
    CgGrid g;
    g.set_axis(2, z_lo, z_hi, nz);
    return g;
  }
  // Two resolved axes (e.g. 0 and 2 for an x-z plane averaged over y).
  static CgGrid plane(int axis_a, double a_lo, double a_hi, int na, int axis_b, double b_lo,
                      double b_hi, int nb) {
    CgGrid g;
    g.set_axis(axis_a, a_lo, a_hi, na);
    g.set_axis(axis_b, b_lo, b_hi, nb);
    return g;
  }
  static CgGrid volume(const Vec3& inLo, const Vec3& inHi, int nx, int ny, int nz) {
    CgGrid g;
    g.set_axis(0, inLo.x, inHi.x, nx);
    g.set_axis(1, inLo.y, inHi.y, ny);
    g.set_axis(2, inLo.z, inHi.z, nz);
    return g;
  }

  void set_axis(int axis, double a_lo, double a_hi, int count) {
    if (count < 1 || (count == 1 && a_hi != a_lo) || a_hi < a_lo)
      throw std::invalid_argument("CgGrid: need count >= 1 and lo <= hi (lo == hi for one point)");
    resolved[axis] = true;
    n[axis] = count;
    lo[axis] = a_lo;
    hi[axis] = a_hi;
  }

  int dim() const { return int(resolved[0]) + int(resolved[1]) + int(resolved[2]); }
  int size() const { return n[0] * n[1] * n[2]; }
  double spacing(int axis) const { return n[axis] > 1 ? (hi[axis] - lo[axis]) / (n[axis] - 1) : 0; }
  double coordinate(int axis, int i) const { return lo[axis] + i * spacing(axis); }
  // x fastest, then y, then z.
  int index(int ix, int iy, int iz) const { return ix + n[0] * (iy + n[1] * iz); }
  // Grid point k; averaged axes read 0.
  Vec3 point(int k) const {
    const int ix = k % n[0], iy = (k / n[0]) % n[1], iz = k / (n[0] * n[1]);
    return {coordinate(0, ix), coordinate(1, iy), coordinate(2, iz)};
  }
};

}  // namespace talus
