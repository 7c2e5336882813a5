#pragma once
// Parameters of one kind of contact (a pair of species, or a species and a wall material).
#include <cmath>
#include <cstdint>
#include <string>

namespace talus {

// A damping coefficient eta (N s/m, or N m s for rolling) that may scale with the reduced
// mass m_ij of the contact: eta = coefficient + per_reduced_mass * m_ij
//                                 + per_sqrt_reduced_mass * sqrt(m_ij).
// Every convention of the literature is one of these terms:
//  - a plain coefficient (Weinhart et al. 2012, Eq. 3 read literally);
//  - a rate per unit reduced mass, eta = gamma m_ij (Silbert et al. 2001, used by
//    Weinhart et al. 2012 Sect. 5 and LAMMPS gran/hooke);
//  - a "damping factor" gamma = eta/(2 m_ij) (Huet et al. 2021, Table I and Sect. V C);
//  - a restitution coefficient e_n at stiffness k_n (Huet et al. 2021, Eq. 17), which is
//    proportional to sqrt(m_ij).
struct DampingLaw {
  double coefficient = 0;            ///< N s/m
  double per_reduced_mass = 0;       ///< 1/s
  double per_sqrt_reduced_mass = 0;  ///< N s/m per sqrt(kg)

  double at(double reduced_mass) const {
    double eta = coefficient + per_reduced_mass * reduced_mass;
    if (per_sqrt_reduced_mass != 0) eta += per_sqrt_reduced_mass * std::sqrt(reduced_mass);
    return eta;
  }
  bool is_zero() const {
    return coefficient == 0 && per_reduced_mass == 0 && per_sqrt_reduced_mass == 0;
  }
};

struct RollingParams {
  bool enabled = false;
  double friction = 0;          ///< mu_r, static rolling friction coefficient (Huet et al. 2021, Eq. A5)
  // When true, k_r and eta_r follow the normal parameters (Huet et al. 2021, Eq. A9):
  // k_r = 3 k_n mu_r^2 R^2, eta_r = 3 eta_n mu_r^2 R^2, with R = 2 R_ij (the radius for equal
  // spheres, twice the sphere radius against a wall).
  bool from_normal = true;
  double stiffness = 0;         ///< N m/rad, k_r when !from_normal
  double damping = 0;           ///< N m s/rad, eta_r when !from_normal
};

// Whether a dashpot follows the contact's stiffness. With a stiffness that grows with the
// overlap (Hertz), Tsuji et al. (1992) take eta proportional to sqrt(m* k(delta)), so that the
// restitution does not depend on the impact speed; for a linear spring both are the same.
enum class DampingScaling : std::uint8_t {
  constant,  ///< eta as DampingLaw gives it
  tsuji,     ///< eta = DampingLaw * sqrt(k_eff / k_n) (Tsuji et al. 1992)
};

// How k_t follows the contact.
enum class TangentialStiffness : std::uint8_t {
  constant,  ///< k_t, N/m
  mindlin,   ///< k_t = 8 G* sqrt(R* delta) (Mindlin 1949, no-slip), tangential_stiffness = 8 G*, Pa
};

// Whether the normal force may pull. A dashpot that separates the pair faster than the spring
// pushes would pull it back; Huet et al. 2021, Eq. (5) bounds the force at zero, Weinhart et
// al. 2012, Eq. (3) does not.
enum class NormalClamp : std::uint8_t {
  by_model,  ///< the shorthands' convention: clamped, except under the elastic-spring model
  clamped,   ///< max(F_n, 0)
  free,      ///< F_n as the spring and dashpot give it
};

struct ContactParams {
  // Hot fields, gathered by offset in the vector sphere batch: doubles only.
  double normal_stiffness = 0;       ///< k_n, N/m (linear) or 4/3 E*, Pa (Hertz)
  DampingLaw normal_damping;         ///< eta_n
  double tangential_stiffness = 0;   ///< k_t, N/m (constant) or 8 G*, Pa (Mindlin)
  DampingLaw tangential_damping;     ///< eta_t
  double friction = 0;               ///< mu_c, Coulomb sliding coefficient
  RollingParams rolling;
  // Cold fields: what the time step needs.
  double impact_speed = 0;           ///< m/s, the fastest expected impact (sets a Hertz contact time)
  std::uint8_t normal_law = 0;       ///< index in the NormalLaws registry (contact/normal_laws.h); 0 is linear
  DampingScaling damping_scaling = DampingScaling::constant;
  TangentialStiffness tangential_law = TangentialStiffness::constant;
  NormalClamp clamp = NormalClamp::by_model;
};

}  // namespace talus
