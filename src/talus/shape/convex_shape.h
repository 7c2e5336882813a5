#pragma once
// Convex shapes for contact: Sphere, Box, Cylinder (axis z) and ConvexPolyhedron, each centred
// at its local origin, held in a closed std::variant (no virtual calls in the hot path).
//
// A ConvexShape keeps two geometries:
//   geometry : the nominal, sharp shape (mass properties, manifolds, plane contact points);
//   core     : the shape eroded by the crust thickness c.
// The contact shape is core (+) ball(c) (Minkowski sum), i.e. the nominal shape with edges and
// corners rounded by c; the narrow phase runs GJK distance between cores (GRAINS3D crust,
// Wachs et al., Powder Technol. 2012). Faces of the contact shape coincide with the nominal faces.
// Choice for polyhedra: the core is the exact erosion (each face plane moved in by c, vertices
// recomputed through the dual hull), not vertices pulled to the centre, so flat faces stay
// where they were and only edges/corners are rounded. A sphere's core is its centre (c = radius).
//
// support(shape, d)          : farthest point of the contact shape along d (local frame)
// support_core(shape, d)     : same for the core
// aabb(shape, pose)          : world box of the contact shape
// contains(geometry, p)      : point-in-nominal-shape test (mass quadrature)
#include <variant>
#include <vector>

#include "talus/math/vec3.h"
#include "talus/shape/convex_hull.h"
#include "talus/shape/pose.h"

namespace talus {

struct Sphere {
  double radius = 0;  ///< (m)
};
struct Box {
  Vec3 half_extents;  ///< half side lengths along local x, y, z (m)
};
struct Cylinder {
  double radius = 0;       ///< (m)
  double half_height = 0;  ///< half length along local z (m)
};
struct ConvexPolyhedron {
  ConvexHull hull;  ///< vertices in the local frame (m)
};

using ConvexGeometry = std::variant<Sphere, Box, Cylinder, ConvexPolyhedron>;
enum class ShapeKind { kSphere = 0, kBox = 1, kCylinder = 2, kPolyhedron = 3 };

struct ConvexShape {
  ConvexGeometry geometry;       ///< nominal sharp shape
  ConvexGeometry core;           ///< geometry eroded by crust
  double crust = 0;              ///< crust thickness = rounding radius of the contact shape (m)
  double bounding_radius = 0;    ///< radius of a ball about the local origin holding the shape (m)

  ShapeKind kind() const { return static_cast<ShapeKind>(geometry.index()); }
};

struct Aabb {
  Vec3 lo, hi;  ///< (m)
};

// Factories. crust must be below the smallest half dimension (throws std::invalid_argument).
ConvexShape make_sphere(double radius);
ConvexShape make_box(const Vec3& half_extents, double crust = 0);
ConvexShape make_cylinder(double radius, double half_height, double crust = 0);
// Hull of the points; the local origin must lie inside it (it need not be the centroid).
ConvexShape make_polyhedron(const std::vector<Vec3>& points, double crust = 0);

Vec3 support(const ConvexGeometry& g, const Vec3& d);  // d need not be unit; zero d gives a valid point
inline Vec3 support_core(const ConvexShape& s, const Vec3& d) { return support(s.core, d); }
inline Vec3 support(const ConvexShape& s, const Vec3& d) {
  return support(s.core, d) + normalized_or_zero(d) * s.crust;
}

Aabb aabb(const ConvexShape& s, const Pose& pose);   // contact shape (core + crust)
Aabb aabb(const ConvexGeometry& g, const Pose& pose);  // a geometry alone, e.g. the nominal one
double bounding_radius(const ConvexGeometry& g);
bool contains(const ConvexGeometry& g, const Vec3& p);

// Contact shape placed in the world: the support-mapping concept used by GJK/EPA.
struct PosedSupport {
  const ConvexGeometry* geometry;
  Pose pose;
  double rounding = 0;  ///< extra ball radius added to the support (m)
  Vec3 support(const Vec3& d) const {
    const Vec3 local = talus::support(*geometry, pose.orientation.rotate_inverse(d));
    return pose.to_parent(local) + normalized_or_zero(d) * rounding;
  }
  Vec3 centre() const { return pose.position; }
};

}  // namespace talus
