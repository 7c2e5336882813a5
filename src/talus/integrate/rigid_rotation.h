#pragma once
// Free rotation of a rigid body with anisotropic inertia, for the drift of the kick-drift-kick
// step. The kicked quantity is the angular momentum (L += h tau); the drift advances the
// orientation and the body-frame angular momentum by the torque-free flow.
#include "talus/math/quat.h"
#include "talus/math/vec3.h"

namespace talus {

// Body-frame angular momentum I w_b of a body with world angular velocity w (rad/s).
// inv_inertia: 1/(kg m^2), principal moments' inverses, all > 0.
inline Vec3 body_momentum(const Quat& q, const Vec3& inv_inertia, const Vec3& w) {
  const Vec3 wb = q.rotate_inverse(w);
  return {wb.x / inv_inertia.x, wb.y / inv_inertia.y, wb.z / inv_inertia.z};
}

// World angular velocity q (I^-1 L_b) q^-1 from the body-frame angular momentum L_b (kg m^2/s).
inline Vec3 world_angular_velocity(const Quat& q, const Vec3& inv_inertia, const Vec3& l_body) {
  return q.rotate(hadamard(inv_inertia, l_body));
}

// Advances ioOrientation (body to world) and ioBodyMomentum over dt (s) by the torque-free
// flow, with the symplectic, time-reversible splitting H = H_symmetric_top + H_residual,
// residual(dt/2) top(dt) residual(dt/2), each part solved exactly (Fasso, J. Comput. Phys. 189,
// 527 (2003); cf. Dullweber, Leimkuhler & McLachlan, J. Chem. Phys. 107, 5840 (1997)).
// |L_b| and the world L = q L_b q^-1 are kept to round-off, the energy error stays bounded,
// O(dt^2), and an axisymmetric body (two equal moments) turns exactly. q is returned normalised.
void free_rotation(Quat& ioOrientation, Vec3& ioBodyMomentum, const Vec3& inv_inertia, double dt);

}  // namespace talus
