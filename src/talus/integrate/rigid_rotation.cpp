#include "talus/integrate/rigid_rotation.h"

#include <cmath>

namespace talus {
namespace {

// cos and sin of an angle. A step turns a body by far less than 0.01 rad, where the Taylor
// series to x^7 is exact to rounding (the next term is below 3e-22 relative) and costs a few
// multiplications instead of a libm call; larger angles go to libm.
void cos_sin(double x, double& c, double& s) {
  if (std::abs(x) < 1e-2) {
    const double x2 = x * x;
    s = x * (1 - x2 / 6 * (1 - x2 / 20 * (1 - x2 / 42)));
    c = 1 - x2 / 2 * (1 - x2 / 12 * (1 - x2 / 30 * (1 - x2 / 56)));
    return;
  }
  c = std::cos(x);
  s = std::sin(x);
}

// q * (cos(phi/2), sin(phi/2) u) for a unit body-frame axis u, given ch = cos(phi/2), sh = sin(phi/2).
Quat turn(const Quat& q, const Vec3& u, double ch, double sh) {
  const Vec3 v = q.vec();
  const Vec3 r = ch * v + (sh * q.w) * u + sh * cross(v, u);
  return {q.w * ch - sh * dot(v, u), r.x, r.y, r.z};
}

// Exact flow over t of H = coef L_k^2 / 2 (coef in 1/(kg m^2)): the body turns by
// phi = t coef L_k about its principal axis k, so the body-frame momentum turns by -phi about
// e_k while the world-frame momentum stays put.
void turn_about_axis(Quat& q, Vec3& l, int k, double coef, double t) {
  const double half = 0.5 * t * coef * l[k];
  double ch, sh;
  cos_sin(half, ch, sh);
  const double c = 1 - 2 * sh * sh, s = 2 * sh * ch;  // cos, sin of phi
  const int a = (k + 1) % 3, b = (k + 2) % 3;          // e_a x e_b = e_k
  const double la = l[a], lb = l[b];
  l[a] = c * la + s * lb;
  l[b] = c * lb - s * la;
  Vec3 e;
  e[k] = 1;
  q = turn(q, e, ch, sh);
}

}  // namespace

void free_rotation(Quat& q, Vec3& l, const Vec3& inv_i, double dt) {
  // The two closest inverse moments (a, b) make the symmetric top, c is its symmetry axis;
  // the residual coef_b L_b^2 / 2 vanishes for an axisymmetric body.
  const double dxy = std::abs(inv_i.x - inv_i.y), dyz = std::abs(inv_i.y - inv_i.z),
               dzx = std::abs(inv_i.z - inv_i.x);
  const int c = (dxy <= dyz && dxy <= dzx) ? 2 : (dyz <= dzx ? 0 : 1);
  const int a = (c + 1) % 3, b = (c + 2) % 3;
  const double inv_sym = inv_i[a], coef_b = inv_i[b] - inv_sym, coef_c = inv_i[c] - inv_sym;

  // An axisymmetric body (equal moments, not merely close: mass_properties) has no residual.
  const bool residual = coef_b != 0;
  if (residual) turn_about_axis(q, l, b, coef_b, 0.5 * dt);
  // Symmetric top |L|^2 / (2 I_a) + coef_c L_c^2 / 2: the two terms commute, so its exact flow
  // is a turn by |L| dt / I_a about L itself (which leaves L_b unchanged) and a turn about e_c.
  const double l_norm = norm(l);
  if (l_norm > 0) {
    const double half = 0.5 * dt * inv_sym * l_norm;
    double ch, sh;
    cos_sin(half, ch, sh);
    q = turn(q, l / l_norm, ch, sh);
  }
  turn_about_axis(q, l, c, coef_c, dt);
  if (residual) turn_about_axis(q, l, b, coef_b, 0.5 * dt);
  q = q.normalized();
}

}  // namespace talus
