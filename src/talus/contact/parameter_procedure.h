#pragma once
// Contact-parameter procedures: from material-level targets (restitution, largest overlap,
// impact speed) to the spring-dashpot coefficients, and back.
namespace talus::params {

// Reduced mass m_ij = m_i m_j / (m_i + m_j); an infinite mass (fixed particle, wall) is 0 inverse mass.
double reduced_mass(double inv_mass_i, double inv_mass_j);

// Huet et al. 2021, Eq. (12): duration of a two-body contact with restitution e_n.
double contact_time(double kn, double reduced_mass, double restitution);
// Huet et al. 2021, Eq. (11): restitution of a linear spring-dashpot (eta_n the coefficient).
double restitution(double kn, double eta_n, double reduced_mass);
// Huet et al. 2021, Eq. (16): k_n giving a largest overlap delta_max at impact speed v_max.
double normal_stiffness_for_overlap(double reduced_mass, double v_max, double delta_max, double restitution);
// Huet et al. 2021, Eq. (13): largest overlap of a head-on impact at speed v_max.
double max_overlap(double kn, double reduced_mass, double v_max, double restitution);
// Huet et al. 2021, Eq. (17): eta_n for restitution e_n.
double normal_damping(double kn, double reduced_mass, double restitution);

struct TangentialCoefficients {
  double stiffness = 0;  ///< k_t, N/m
  double damping = 0;    ///< eta_t, N s/m
};
// Huet et al. 2021, Eqs. (18)-(19), after Pournin et al.: k_t and eta_t from the normal
// parameters and the tangential restitution e_t (I: moments of inertia about the rolling axes).
TangentialCoefficients pournin_tangential(double kn, double eta_n, double reduced_mass, double radius_i,
                                          double inertia_i, double radius_j, double inertia_j,
                                          double restitution_n, double restitution_t);

struct RollingCoefficients {
  double stiffness = 0;  ///< k_r, N m/rad
  double damping = 0;    ///< eta_r, N m s/rad
};
// Huet et al. 2021, Eq. (A9): k_r = 3 k_n mu_r^2 R^2, eta_r = 3 eta_n mu_r^2 R^2.
RollingCoefficients rolling_from_normal(double kn, double eta_n, double rolling_friction, double radius);

// Weinhart et al. 2012, Eq. (5): collision time for damping coefficient gamma_n (force per velocity).
double collision_time(double kn, double gamma_n, double reduced_mass);
// Weinhart et al. 2012, Eq. (6): restitution r_c = exp(-t_c gamma_n / (2 m_ij)).
double restitution_from_collision(double kn, double gamma_n, double reduced_mass);

}  // namespace talus::params
