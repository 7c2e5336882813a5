#pragma once
// The contact law, assembled from sub-models, each taking the contact geometry explicitly:
// normal (contact/normal_laws.h: linear, Hertz) with its dashpot (DampingLaw, optionally
// following the stiffness after Tsuji) and clamp; tangential (the TangentialModel history
// rule, with a constant or Mindlin stiffness); rolling (Huet et al. 2021, App. A, or none).
// One function serves sphere pairs, particle-wall contacts and every contact point between
// convex parts; the vector sphere batch (world/sphere_elastic_batch.h) is this law line for line.
#include <algorithm>
#include <cmath>
#include <type_traits>

#include "talus/contact/contact_params.h"
#include "talus/contact/normal_laws.h"
#include "talus/math/vec3.h"

namespace talus {

// How the tangential force remembers the contact's past.
enum class TangentialModel {
  memory,          ///< cumulative displacement rotated with the tangent plane (Huet et al. 2021, Eqs. 6-8)
  memoryless,      ///< viscous friction only, k_t delta_t and k_r dtheta dropped (Huet et al. 2021, Sect. V B)
  elastic_spring,  ///< elastic displacement kept tangential by Eq. 9 (Weinhart et al. 2012, Eqs. 7-9, Alg. 2)
};

inline const char* tangential_model_name(TangentialModel m) {
  switch (m) {
    case TangentialModel::memoryless: return "memoryless";
    case TangentialModel::elastic_spring: return "elastic_spring";
    case TangentialModel::memory: break;
  }
  return "memory";
}

struct ContactGeometry {
  Vec3 normal;               ///< unit normal, from j (or the wall) towards i
  double overlap = 0;        ///< m, delta_n > 0
  Vec3 arm_i;                ///< m, contact point minus centre of i
  Vec3 arm_j;                ///< m, contact point minus centre of j (zero for a wall)
  double inv_distance = 0;   ///< 1/m, 1/|r_ij| for the Eq. 9 rotation term; 0 when the normal cannot turn (walls)
};

struct ContactMotion {
  Vec3 velocity_i, angular_velocity_i;  ///< m/s, rad/s
  Vec3 velocity_j, angular_velocity_j;  ///< m/s, rad/s (a wall's velocity at the contact point, zero spin)
};

// Per-contact memory. Zero when the pair is not in contact: a new contact starts from rest.
struct ContactHistoryRef {
  Vec3* spring = nullptr;        ///< m, delta_t: cumulative (memory) or elastic (elastic_spring) tangential displacement
  Vec3* normal_prev = nullptr;   ///< the normal at the previous step, zero before the first (may be null for elastic_spring)
  Vec3* rolling = nullptr;       ///< N m, spring part M_k of the rolling torque (null when rolling is off)
};

struct ContactResult {
  Vec3 force_on_i;         ///< N, the force on i (j receives the opposite)
  Vec3 torque_i;           ///< N m, about the centre of i
  Vec3 torque_j;           ///< N m, about the centre of j
  double normal_force = 0; ///< N, |F_n|
};

// Calls f(std::integral_constant<TangentialModel, M>) for the runtime model: the hot loops are
// compiled once per model and the choice is made once per call, not per contact.
template <class F>
decltype(auto) with_tangential_model(TangentialModel model, F&& f) {
  switch (model) {
    case TangentialModel::memoryless: return f(std::integral_constant<TangentialModel, TangentialModel::memoryless>{});
    case TangentialModel::elastic_spring:
      return f(std::integral_constant<TangentialModel, TangentialModel::elastic_spring>{});
    case TangentialModel::memory: break;
  }
  return f(std::integral_constant<TangentialModel, TangentialModel::memory>{});
}

// Rotates v by the smallest rotation taking unit vector a onto unit vector b. This is the
// q_rot of Huet et al. 2021, Eq. (8), written in closed form (Rodrigues):
// R v = v + w x v + w x (w x v) / (1 + a.b), w = a x b.
inline Vec3 rotate_between(const Vec3& a, const Vec3& b, const Vec3& v) {
  const Vec3 w = cross(a, b);
  const double c = dot(a, b);
  if (c <= -1.0 + 1e-12) return -v;  // reversed normal: no unique rotation; a half turn is the limit
  const Vec3 wv = cross(w, v);
  return v + wv + cross(w, wv) * (1.0 / (1.0 + c));
}

// The spring and dashpot coefficients of one contact at its present overlap: the parameters
// for a linear law, grown with the contact radius for Hertz and Mindlin.
struct ContactCoefficients {
  double kn, eta_n, kt, eta_t;  ///< N/m, N s/m
};

[[gnu::always_inline]] inline ContactCoefficients contact_coefficients(const ContactParams& p, double reduced_mass,
                                                                       double reduced_radius, double overlap) {
  ContactCoefficients c{p.normal_stiffness, p.normal_damping.at(reduced_mass), p.tangential_stiffness,
                        p.tangential_damping.at(reduced_mass)};
  if (p.normal_law != 0) [[unlikely]] {
    const double s = normal_stiffness_scale(p.normal_law, reduced_radius, overlap);
    c.kn *= s;
    if (p.damping_scaling == DampingScaling::tsuji) {  // Tsuji et al. 1992: eta ~ sqrt(m* k_eff)
      const double d = std::sqrt(s);
      c.eta_n *= d;
      c.eta_t *= d;
    }
  }
  if (p.tangential_law == TangentialStiffness::mindlin) [[unlikely]]
    c.kt *= std::sqrt(reduced_radius * overlap);  // Mindlin 1949: k_t = 8 G* a
  return c;
}

// The dashpot a sliding contact's spring is reset against (Huet et al. 2021, Eq. 8; Weinhart et
// al. 2012, Alg. 2): the spring takes what the dashpot leaves of the Coulomb force. When the
// coefficients change with the overlap (Mindlin's k_t ~ a, Tsuji's eta ~ sqrt(a)) a dashpot much
// above the Coulomb force leaves a large spring cancelling a large dashpot, and at the next
// step, both scaled by different factors, their difference may point along the slip. There the
// spring alone holds the Coulomb force (Cundall and Strack 1979) and the dashpot acts on top.
inline bool coefficients_grow(const ContactParams& p) {
  return p.tangential_law == TangentialStiffness::mindlin || p.damping_scaling == DampingScaling::tsuji;
}
inline double sliding_dashpot(const ContactParams& p, double eta_t) { return coefficients_grow(p) ? 0.0 : eta_t; }

// Whether the normal force is bounded at zero under tangential model `model`.
inline bool clamps_normal(const ContactParams& p, TangentialModel model) {
  return p.clamp == NormalClamp::clamped || (p.clamp == NormalClamp::by_model && model != TangentialModel::elastic_spring);
}

// Elastic energy of the normal spring: the integral of k_n s(delta) delta, k_eff delta^2 / (p + 1).
inline double normal_elastic_energy(const ContactParams& p, double kn_eff, double overlap) {
  return kn_eff * overlap * overlap / (normal_exponent(p.normal_law) + 1);
}

template <TangentialModel Model>
[[gnu::always_inline]] inline ContactResult contact_force(const ContactGeometry& g, const ContactMotion& m,
                                   const ContactParams& p, double reduced_mass,
                                   double reduced_radius, double dt, ContactHistoryRef h) {
  ContactResult out;
  const Vec3& n = g.normal;
  // Relative velocity of the contact point of i with respect to that of j.
  const Vec3 vij = m.velocity_i - m.velocity_j;
  const Vec3 vc = vij + cross(m.angular_velocity_i, g.arm_i) - cross(m.angular_velocity_j, g.arm_j);
  const double vn = dot(vc, n);  // < 0 while approaching
  const Vec3 vt = vc - vn * n;

  // Normal force. Weinhart et al. 2012, Eq. (3); Huet et al. 2021, Eq. (5) adds max(., 0).
  const ContactCoefficients co = contact_coefficients(p, reduced_mass, reduced_radius, g.overlap);
  const double eta_n = co.eta_n;
  double fn = co.kn * g.overlap - eta_n * vn;
  if (clamps_normal(p, Model)) fn = std::max(fn, 0.0);
  const double fn_abs = std::abs(fn);
  const double f_max = p.friction * fn_abs;
  const double eta_t = co.eta_t;
  const double kt = co.kt;

  Vec3 ft;
  if constexpr (Model == TangentialModel::memory) {
    Vec3& spring = *h.spring;
    // Huet et al. 2021, Eq. (8): carry delta_t into the current tangent plane, then integrate v_t.
    const Vec3& n_prev = *h.normal_prev;
    if (norm2(n_prev) > 0) spring = rotate_between(n_prev, n, spring);
    spring += vt * dt;
    ft = -kt * spring - eta_t * vt;                  // Huet et al. 2021, Eq. (6), before saturation
    const double ft2 = norm2(ft);
    if (ft2 > f_max * f_max) {
      ft *= f_max / std::sqrt(ft2);                  // Eqs. (6)-(7): mu_c |F_n| u_t,cumul
      spring = (kt > 0) ? (ft + sliding_dashpot(p, eta_t) * vt) * (-1.0 / kt) : Vec3{};  // Eq. (8), saturated branch
    }
  } else if constexpr (Model == TangentialModel::elastic_spring) {
    Vec3& spring = *h.spring;
    // Weinhart et al. 2012, Eq. (9) by forward Euler (Alg. 1): the second term turns the spring
    // with the normal so that it stays tangential.
    spring += (vt - (dot(spring, vij) * g.inv_distance) * n) * dt;
    ft = -kt * spring - eta_t * vt;                  // Eq. (7)
    const double ft2 = norm2(ft);
    if (ft2 > f_max * f_max) {
      ft *= f_max / std::sqrt(ft2);                  // Alg. 2: truncate to mu_c |f_n|
      spring = (kt > 0) ? (ft + sliding_dashpot(p, eta_t) * vt) * (-1.0 / kt) : Vec3{};
    }
  } else {
    // Huet et al. 2021, Sect. V B without memory: viscous friction capped by Coulomb.
    ft = -eta_t * vt;
    const double ft2 = norm2(ft);
    if (ft2 > f_max * f_max) ft *= f_max / std::sqrt(ft2);
  }

  out.force_on_i = fn * n + ft;
  out.normal_force = fn_abs;
  out.torque_i = cross(g.arm_i, out.force_on_i);
  out.torque_j = cross(g.arm_j, -out.force_on_i);

  if (p.rolling.enabled) {
    // Huet et al. 2021, Appendix A, Eqs. (A1)-(A5).
    const Vec3 spin = m.angular_velocity_i - m.angular_velocity_j;  // d(theta)/dt, relative rotation rate
    const double m_max = p.rolling.friction * reduced_radius * fn_abs;
    double kr = p.rolling.stiffness, eta_r = p.rolling.damping;
    if (p.rolling.from_normal) {
      const double r = 2.0 * reduced_radius;
      const double scale = 3.0 * p.rolling.friction * p.rolling.friction * r * r;  // Eq. (A9)
      kr = scale * co.kn;
      eta_r = scale * eta_n;
    }
    Vec3 moment;
    if constexpr (Model == TangentialModel::memoryless) {
      moment = -eta_r * spin;
      const double m2 = norm2(moment);
      if (m2 > m_max * m_max) moment *= m_max / std::sqrt(m2);
    } else {
      Vec3& mk = *h.rolling;
      if (h.normal_prev && norm2(*h.normal_prev) > 0) mk = rotate_between(*h.normal_prev, n, mk);
      mk -= kr * dt * spin;                          // Eq. (A2)
      const double mk2 = norm2(mk);
      if (mk2 > m_max * m_max) {
        mk *= m_max / std::sqrt(mk2);                // saturated: M_max u_r,cumul, Eq. (A4); M_d = 0, Eq. (A3)
        moment = mk;
      } else {
        moment = mk - eta_r * spin;                  // Eq. (A3)
      }
    }
    out.torque_i += moment;
    out.torque_j -= moment;
  }
  if (h.normal_prev) *h.normal_prev = n;
  return out;
}

}  // namespace talus
