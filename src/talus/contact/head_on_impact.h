#pragma once
// The head-on impact of one contact: m delta'' = -F_n(delta, delta'), delta(0) = 0,
// delta'(0) = v0, with the force the contact law gives (contact_coefficients). It ends when the
// overlap returns to zero or, with the force clamped at zero (Huet et al. 2021, Eq. 5), when the
// force would pull: from then on nothing acts, so the speed then is the rebound speed.
//
// A dashpot that follows the stiffness as Tsuji et al. (1992) take it (for a linear spring, any
// dashpot) makes the impact one equation for every stiffness, mass and speed: in units of
// T = (m / (K v0^(p-1)))^(1/(p+1)) and v0 T, x'' = -x^p - c x^((p-1)/2) x' with c = eta_n /
// sqrt(m K) at unit overlap (c = 2 zeta for a linear spring). The restitution depends on c alone.
#include <cstdint>

#include "talus/contact/contact_params.h"

namespace talus::params {

struct ImpactOutcome {
  double restitution = 0;  ///< rebound speed / impact speed
  double duration = 0;     ///< s, contact time
};

// Closed form for a linear spring (Huet et al. 2021, Eqs. 11-12 unclamped); classical
// Runge-Kutta in steps of T/1024 otherwise (about 3,300 for a Hertz impact), the exit placed by
// linear interpolation within the last step. A contact still going after 1024 T has crept to
// rest: restitution 0.
ImpactOutcome head_on_impact(const ContactParams& params, double reduced_mass, double reduced_radius, double speed,
                             bool clamp);

// The dimensionless damping c whose impact rebounds with restitution e in (0, 1) under normal
// law `normal_law` (a NormalLaws index), solved, not approximated: Eq. (17) of Huet et al.
// 2021 for an unclamped linear spring, bisection on the impact otherwise. The dashpot is then
// eta_n = c sqrt(m* k_n) for a linear spring, c sqrt(m* k_n sqrt(R*)) delta^(1/4) for Hertz
// (DampingLaw::per_sqrt_reduced_mass = c sqrt(k_n), with DampingScaling::tsuji).
double damping_for_restitution(std::uint8_t normal_law, bool clamp, double restitution);

}  // namespace talus::params
