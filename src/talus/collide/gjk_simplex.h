#pragma once
// The distance sub-algorithm of GJK: given a simplex (1-4 points of the Minkowski difference
// A - B), find the point of its hull closest to the origin and shrink the simplex to the
// smallest face holding it. Voronoi-region tests on edges and faces (Ericson, Real-Time
// Collision Detection, 2005, Sec. 5.1) rather than Johnson's determinant recursion: the
// same result, and degenerate (collinear / flat) simplices fall back to their best face
// instead of dividing by a vanishing determinant.
#include <array>
#include <cstdint>

#include "talus/math/uninitialized_array.h"
#include "talus/math/vec3.h"

namespace talus {

struct SupportPoint {
  Vec3 w;  ///< a - b, a point of the Minkowski difference (m)
  Vec3 a;  ///< support point on A (m)
  Vec3 b;  ///< support point on B (m)
  std::uint32_t corners = 0;  ///< two placed boxes: the corner ids of a (bits 0-2) and b (3-5), box_simplex.h
};

struct Simplex {
  UninitializedArray<SupportPoint, 4> p;  ///< the first `size` are set; a warm-started GJK builds one per query
  std::array<double, 4> lambda{};  ///< barycentric weights of the closest point (after reduce)
  int size = 0;

  void push(const SupportPoint& s) { p[size++] = s; }
  // Copies only the points in use: GJK keeps a copy per iteration, mostly of one or two points.
  void assign(const Simplex& o) {
    for (int k = 0; k < o.size; ++k) p[k] = o.p[k];
    lambda = o.lambda;
    size = o.size;
  }
};

// Shrinks s to the sub-simplex holding the point closest to the origin; returns that point.
// Sets *inside when the origin lies in a full (or flattened) tetrahedron.
Vec3 reduce_simplex(Simplex& s, bool* inside);

}  // namespace talus
