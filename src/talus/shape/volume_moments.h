#pragma once
// Volume integrals of solids about their frame's origin: V, the first moment (int x dV) and the
// second moment (int x x^T dV). Moments of disjoint pieces add, of a union by inclusion-exclusion;
// mass_properties turns them into mass, centre of mass and inertia at a uniform density.
//   moments(geometry)              : a convex part in its own frame
//   transformed(moments, pose)     : the same solid placed by pose
//   polyhedron_moments(hull)       : any closed outward-oriented triangulation
//   spherical_cap_moments(R, h, c, axis) : the cap of height h of a ball (centre c) along axis
#include <Eigen/Dense>

#include "talus/shape/convex_hull.h"
#include "talus/shape/convex_shape.h"
#include "talus/shape/pose.h"

namespace talus {

struct VolumeMoments {
  double volume = 0;                                     ///< (m^3)
  Eigen::Vector3d first = Eigen::Vector3d::Zero();       ///< (m^4)
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();      ///< (m^5)

  VolumeMoments& operator+=(const VolumeMoments& o) {
    volume += o.volume;
    first += o.first;
    second += o.second;
    return *this;
  }
  VolumeMoments operator*(double s) const { return {volume * s, first * s, second * s}; }
};

VolumeMoments transformed(const VolumeMoments& m, const Pose& pose);
VolumeMoments box_moments(const Vec3& half_extents, const Vec3& centre);
VolumeMoments polyhedron_moments(const ConvexHull& hull);
VolumeMoments moments(const ConvexGeometry& g);
// The part of a ball of radius R beyond the plane at distance R - h from its centre, on the side
// `axis` (unit) points to; h in [0, 2R].
VolumeMoments spherical_cap_moments(double radius, double height, const Vec3& centre, const Vec3& axis);

}  // namespace talus
