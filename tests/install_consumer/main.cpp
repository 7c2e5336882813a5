// Two glass beads meet head-on, built and stepped through Talus' installed headers. Exits
// non-zero unless the collision behaves as the linear spring-dashpot says: momentum kept, the
// beads apart again afterwards, and each rebounding at about the chosen restitution.
#include <cmath>
#include <cstdio>
#include <numbers>

#include "talus/contact/parameter_procedure.h"
#include "talus/world/world.h"

using talus::Vec3;

namespace {

constexpr double kRadius = 1e-3;     // m
constexpr double kDensity = 2500;    // kg/m^3
constexpr double kSpeed = 0.5;       // m/s, each bead's speed towards the other
constexpr double kRestitution = 0.7;

talus::ParticleInit bead(const Vec3& position, const Vec3& velocity) {
  talus::ParticleInit p;
  p.position = position;
  p.velocity = velocity;
  p.radius = kRadius;
  p.mass = kDensity * 4.0 / 3.0 * std::numbers::pi * kRadius * kRadius * kRadius;
  const double inertia = 0.4 * p.mass * kRadius * kRadius;
  p.inertia = {inertia, inertia, inertia};
  return p;
}

bool check(bool ok, const char* what) {
  std::printf("%s: %s\n", ok ? "ok  " : "FAIL", what);
  return ok;
}

}  // namespace

int main() {
  const double mass = bead({}, {}).mass;
  const double reduced_mass = mass / 2;
  talus::ContactParams contact;
  contact.normal_stiffness = talus::params::normal_stiffness_for_overlap(reduced_mass, 2 * kSpeed, 0.01 * kRadius, kRestitution);
  contact.normal_damping.coefficient = talus::params::normal_damping(contact.normal_stiffness, reduced_mass, kRestitution);
  contact.friction = 0.5;
  const double contact_time = std::numbers::pi / std::sqrt(contact.normal_stiffness / reduced_mass);

  talus::WorldSettings settings;
  settings.domain = {{-0.01, -0.01, -0.01}, {0.01, 0.01, 0.01}};
  settings.gravity = {0, 0, 0};
  settings.time_step = contact_time / 200;
  talus::World world(settings);
  world.contacts().resize(1, 1);
  world.contacts().set_pair(0, 0, contact);
  world.add_particle(bead({-1.2 * kRadius, 0, 0}, {kSpeed, 0, 0}));
  world.add_particle(bead({1.2 * kRadius, 0, 0}, {-kSpeed, 0, 0}));

  // Long enough to close the 0.4 mm gap, collide, and move apart again.
  const double duration = 0.4 * kRadius / (2 * kSpeed) + 3 * contact_time;
  world.run(static_cast<std::uint64_t>(std::ceil(duration / settings.time_step)));

  const talus::ParticleStore& p = world.particles();
  Vec3 momentum{};
  for (std::size_t i = 0; i < p.owned; ++i) momentum += p.mass[i] * p.velocity[i];
  const double gap = talus::norm(p.position[1] - p.position[0]) - 2 * kRadius;
  const double rebound = std::abs(p.velocity[0][0]);
  std::printf("after %.3g s: gap %.3g m, speeds %.4g and %.4g m/s, momentum %.3g kg m/s, %zu contacts\n",
              world.time(), gap, p.velocity[0][0], p.velocity[1][0], talus::norm(momentum), world.diagnostics().contacts);

  bool ok = check(p.owned == 2, "two beads");
  ok = check(talus::norm(momentum) < 1e-12 * mass * kSpeed, "momentum kept (zero before, zero after)") && ok;
  ok = check(gap > 0 && world.diagnostics().contacts == 0, "beads apart after the collision") && ok;
  ok = check(p.velocity[0][0] * p.velocity[1][0] < 0 && (p.velocity[1][0] - p.velocity[0][0]) * (p.position[1][0] - p.position[0][0]) > 0,
             "beads moving away from each other") && ok;
  // The contact ends when the dashpot would start to pull (no tension), a little before the
  // overlap closes, so the beads leave a little faster than the damped oscillator's e says.
  const double restitution = rebound / kSpeed;
  ok = check(restitution > kRestitution && restitution < kRestitution + 0.05, "rebound at the chosen restitution, up to the no-tension end") && ok;
  return ok ? 0 : 1;
}
