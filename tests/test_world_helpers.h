#pragma once
// Small builders shared by the engine tests.
#include <numbers>

#include "talus/contact/parameter_procedure.h"
#include "talus/world/world.h"

namespace talus::testing {

// Glass-like spheres in SI units with the Huet et al. 2021 parameter procedure: k_n for a
// largest overlap of 0.5 % of the radius at 1 m/s, e_n = 0.5, k_t = 2/7 k_n.
inline ContactParams glass_contact(double radius, double density, double friction, double reduced_mass_factor = 0.5) {
  const double mass = density * 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  const double m_ij = reduced_mass_factor * mass;
  ContactParams c;
  c.normal_stiffness = params::normal_stiffness_for_overlap(m_ij, 1.0, 0.005 * radius, 0.5);
  c.normal_damping.coefficient = params::normal_damping(c.normal_stiffness, m_ij, 0.5);
  c.tangential_stiffness = 2.0 / 7.0 * c.normal_stiffness;
  c.tangential_damping.coefficient = c.normal_damping.coefficient;
  c.friction = friction;
  return c;
}

inline ParticleInit sphere(const Vec3& x, double radius, double density) {
  ParticleInit p;
  p.position = x;
  p.radius = radius;
  p.mass = density * 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  const double i = 0.4 * p.mass * radius * radius;
  p.inertia = {i, i, i};
  return p;
}

}  // namespace talus::testing
