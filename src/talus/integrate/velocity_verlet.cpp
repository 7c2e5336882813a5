#include "talus/integrate/velocity_verlet.h"

#include <algorithm>

#include "talus/world/parallel.h"

namespace talus {

void kick(ParticleStore& p, double h, const Vec3& gravity) {
  const std::size_t n = p.owned;
#pragma omp parallel for schedule(static) if (worth_parallel(n))
  for (std::size_t i = 0; i < n; ++i) {
    const double inv_m = p.inv_mass[i];
    if (inv_m == 0.0) continue;  // fixed particles: infinite mass, unaffected by gravity
    p.velocity[i] += h * (inv_m * p.force[i] + gravity);
    const Vec3 inv_i = p.inv_inertia[i];
    if (inv_i.x == inv_i.y && inv_i.y == inv_i.z) {
      p.angular_velocity[i] += (h * inv_i.x) * p.torque[i];
    } else {
      // Euler's equations in the principal frame; the gyroscopic term is explicit here.
      const Quat& q = p.orientation[i];
      const Vec3 w = q.rotate_inverse(p.angular_velocity[i]);
      const Vec3 t = q.rotate_inverse(p.torque[i]);
      const Vec3 l{w.x / inv_i.x, w.y / inv_i.y, w.z / inv_i.z};
      const Vec3 dw = hadamard(inv_i, t - cross(w, l)) * h;
      p.angular_velocity[i] = q.rotate(w + dw);
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
    Quat& q = p.orientation[i];
    const Quat dq = Quat{0, w.x, w.y, w.z} * q;
    q = Quat{q.w + 0.5 * dt * dq.w, q.x + 0.5 * dt * dq.x, q.y + 0.5 * dt * dq.y, q.z + 0.5 * dt * dq.z}
            .normalized();
    max_d2 = std::max(max_d2, norm2(p.position[i] - at_build[i]));
  }
  return max_d2;
}

}  // namespace talus
