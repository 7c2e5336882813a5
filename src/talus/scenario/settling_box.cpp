#include "talus/scenario/settling_box.h"

#include <numbers>
#include <random>

#include "talus/contact/parameter_procedure.h"
#include "talus/scenario/insertion.h"

namespace talus {

namespace {
// Huet et al. 2021, Sect. II C 2: k_n from delta_max at v_max = 1 m/s (Eq. 16), eta_n from e_n
// (Eq. 17), k_t and eta_t after Pournin (Eqs. 18-19) with e_t = e_n.
ContactParams procedure_params(double mass, double radius, double reduced_factor, double e, double overlap,
                               double mu, double mu_r) {
  const double m_ij = reduced_factor * mass;
  const double inertia = 0.4 * mass * radius * radius;
  ContactParams c;
  c.normal_stiffness = params::normal_stiffness_for_overlap(m_ij, 1.0, overlap * radius, e);
  const double eta_n = params::normal_damping(c.normal_stiffness, m_ij, e);
  c.normal_damping.coefficient = eta_n;
  const auto t = params::pournin_tangential(c.normal_stiffness, eta_n, m_ij, radius, inertia,
                                            reduced_factor < 1 ? radius : 0.0, reduced_factor < 1 ? inertia : 0.0, e, e);
  c.tangential_stiffness = t.stiffness;
  c.tangential_damping.coefficient = t.damping;
  c.friction = mu;
  c.rolling.enabled = mu_r > 0;
  c.rolling.friction = mu_r;
  return c;
}
}  // namespace

std::unique_ptr<World> build_settling_box(const SettlingBoxSetup& s) {
  const double mass = s.density * 4.0 / 3.0 * std::numbers::pi * s.radius * s.radius * s.radius;
  const ContactParams pp = procedure_params(mass, s.radius, 0.5, s.restitution, s.max_overlap, s.friction,
                                            s.rolling_friction);
  const ContactParams pw = procedure_params(mass, s.radius, 1.0, s.restitution, s.max_overlap, s.wall_friction,
                                            s.wall_rolling_friction);
  WorldSettings ws;
  ws.domain = {{0, 0, 0}, s.box};
  ws.gravity = {0, 0, -9.81};
  ws.tangential_model = s.model;
  ws.time_step = params::contact_time(pp.normal_stiffness, 0.5 * mass, s.restitution) / s.steps_per_contact;
  auto world = std::make_unique<World>(ws);
  world->contacts().resize(1, 1);
  world->contacts().set_pair(0, 0, pp);
  world->contacts().set_wall(0, 0, pw);
  const Vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const Vec3& n : normals) {
    Wall w;
    w.normal = n;
    w.origin = {n.x < 0 ? s.box.x : 0, n.y < 0 ? s.box.y : 0, n.z < 0 ? s.box.z : 0};
    world->add_wall(w);
  }
  std::mt19937_64 rng(s.seed);
  const bool closed[3] = {false, false, false};
  SphereOverlapIndex index({0, 0, 0}, s.box, closed, 2 * s.radius);
  const Vec3 margin{s.radius, s.radius, s.radius};
  const Vec3 region = s.box - 2.0 * margin;
  insert_growing(index, s.count, margin, {region.x, region.y, 0.3 * region.z}, 1e-3 * s.radius,
                 [&](std::mt19937_64&) { return s.radius; }, rng, region.z);
  for (const PlacedSphere& sp : index.spheres()) world->add_sphere(sp.centre, sp.radius, s.density, 0);
  return world;
}

}  // namespace talus
