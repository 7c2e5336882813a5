#pragma once
// The contact geometry of two spheres, handed to the contact law: the kernel of the sphere
// pair loops.
#include <cmath>

#include "talus/contact/contact_law.h"

namespace talus {

// The contact of two spheres whose centres are d = x_i - x_j apart, dist2 = |d|^2 < (r_i + r_j)^2.
template <TangentialModel Model>
[[gnu::always_inline]] inline ContactResult sphere_contact(const Vec3& d, double dist2, double ri, double rj,
                                                           const ContactMotion& m, const ContactParams& params,
                                                           double reduced_mass, double memory_dt,
                                                           const ContactHistoryRef& h) {
  const double reach = ri + rj;
  const double dist = std::sqrt(dist2);
  const double inv_dist = 1.0 / dist;
  ContactGeometry g;
  g.normal = d * inv_dist;
  g.overlap = reach - dist;
  g.arm_i = g.normal * -(ri - 0.5 * g.overlap);  // Weinhart et al. 2012, branch vector b_ij after Eq. (8)
  g.arm_j = g.normal * (rj - 0.5 * g.overlap);
  g.inv_distance = inv_dist;
  const bool needs_radius = params.rolling.enabled || params.normal_law != 0 ||
                            params.tangential_law != TangentialStiffness::constant;
  const double reduced_radius = needs_radius ? ri * rj / reach : 0.0;
  return contact_force<Model>(g, m, params, reduced_mass, reduced_radius, memory_dt, h);
}

}  // namespace talus
