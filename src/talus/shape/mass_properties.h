#pragma once
// Mass properties from geometry at a uniform density: volume, mass, centre of mass, inertia
// tensor about the centre of mass, principal moments and axes.
//   mass_properties(geometry | shape | composite, density)
// A ConvexShape uses its nominal (sharp) geometry; the crust only affects contact.
// Composites count overlapping volume once:
//   - exactly when every part is a box whose axes map onto the body axes (coordinate
//     compression into disjoint cells; e.g. the Huet cross, V = 2*27*2*3 - 2*2*3 mm^3);
//   - else exactly by inclusion-exclusion over the parts that meet, when every common volume
//     has a closed form (part_intersection.h: any polyhedral parts at any angle, two balls, a
//     ball capping a cylinder, parts apart): crosses at any angle, stellated octahedra, rods,
//     tetrapods, mesh unions;
//   - otherwise (e.g. two crossing cylinders) as the exact sum over parts minus a
//     midpoint-rule quadrature of the multiply covered volume on a node grid refined x8 in
//     boundary cells (only the overlap is approximated; error O(cell size x overlap surface):
//     measured 2e-5 of the overlap for two spheres, 1e-3 of the overlap = 4e-5 of the total
//     for a cross rotated off the body axes, 0.2-0.5 s offline; see test_shape_mass.cpp).
// To store a body in its principal frame: principal_pose() is that frame in the shape frame;
// to_principal_frame() re-expresses a composite's part poses in it.
#include <Eigen/Dense>

#include "talus/shape/composite_shape.h"
#include "talus/shape/convex_shape.h"
#include "talus/shape/pose.h"

namespace talus {

struct MassProperties {
  double volume = 0;                               ///< (m^3)
  double mass = 0;                                 ///< (kg)
  Vec3 centre_of_mass;                             ///< in the shape frame (m)
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  ///< about the centre of mass, shape axes (kg m^2)
  Vec3 principal_moments;                          ///< ascending (kg m^2)
  Quat principal_orientation;                      ///< rotation principal frame -> shape frame

  Pose principal_pose() const { return {centre_of_mass, principal_orientation}; }
};

struct CompositeMassOptions {
  int quadrature_cells = 64;  ///< cells along the longest side of the overlap region (x8 at boundaries)
  bool force_quadrature = false;  ///< skip the exact paths (for testing the quadrature)
};

MassProperties mass_properties(const ConvexGeometry& g, double density);
MassProperties mass_properties(const ConvexShape& s, double density);
MassProperties mass_properties(const CompositeShape& c, double density, const CompositeMassOptions& options = {});

// The composite with part poses expressed in the principal frame of mp.
CompositeShape to_principal_frame(const CompositeShape& c, const MassProperties& mp);

}  // namespace talus
