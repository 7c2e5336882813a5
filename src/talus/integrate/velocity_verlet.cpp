#include "talus/integrate/velocity_verlet.h"

#include <algorithm>

#include "talus/integrate/rigid_rotation.h"
#include "talus/world/parallel.h"

namespace talus {
namespace {
// Equal principal moments: omega and L are parallel and the free flow is a steady rotation.
inline bool isotropic(const Vec3& inv_i) { return inv_i.x == inv_i.y && inv_i.y == inv_i.z; }
}  // namespace

void kick(ParticleStore& p, double h, const Vec3& gravity) {
  const std::size_t n = p.owned;
#pragma omp parallel for schedule(static) if (worth_parallel(n))
  for (std::size_t i = 0; i < n; ++i) {
    const double inv_m = p.inv_mass[i];
    if (inv_m == 0.0) continue;  // fixed particles: infinite mass, unaffected by gravity
    p.velocity[i] += h * (inv_m * p.force[i] + gravity);
    const Vec3 inv_i = p.inv_inertia[i];
    if (isotropic(inv_i)) {
      p.angular_velocity[i] += (h * inv_i.x) * p.torque[i];
    } else {
      // L += h tau at fixed orientation; the gyroscopic term is in the drift's free flow.
      const Quat& q = p.orientation[i];
      p.angular_velocity[i] += h * q.rotate(hadamard(inv_i, q.rotate_inverse(p.torque[i])));
    }
  }
}

double drift(ParticleStore& p, double dt, const std::vector<Vec3>& at_build) {
  const std::size_t n = p.owned;
  double max_d2 = 0;
#pragma omp parallel for schedule(static) reduction(max : max_d2) if (worth_parallel(n))
  for (std::size_t i = 0; i < n; ++i) {
    if (p.inv_mass[i] == 0.0) continue;
    p.position[i] += dt * p.velocity[i];
    const Vec3 w = p.angular_velocity[i];
    const Vec3 inv_i = p.inv_inertia[i];
    Quat& q = p.orientation[i];
    if (isotropic(inv_i)) {
      // A sphere's orientation plays no part in its dynamics: only shaped bodies track it.
      // Free rotation of an isotropic body is a steady turn about omega.
      if (p.shape[i] != 0) {
        const double angle = norm(w) * dt;
        if (angle > 0) q = (Quat::from_axis_angle(w, angle) * q).normalized();
      }
    } else {
      Vec3 l = body_momentum(q, inv_i, w);
      free_rotation(q, l, inv_i, dt);
      p.angular_velocity[i] = world_angular_velocity(q, inv_i, l);
    }
    max_d2 = std::max(max_d2, norm2(p.position[i] - at_build[i]));
  }
  return max_d2;
}

}  // namespace talus
