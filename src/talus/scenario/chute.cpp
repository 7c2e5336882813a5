#include "talus/scenario/chute.h"

#include <cmath>
#include <numbers>
#include <random>

#include "talus/contact/parameter_procedure.h"
#include "talus/scenario/insertion.h"

namespace talus {

ContactParams weinhart_chute_contact() {
  ContactParams c;
  c.normal_stiffness = 2e5;
  c.normal_damping.per_reduced_mass = 50;
  c.tangential_stiffness = 2.0 / 7.0 * 2e5;
  c.tangential_damping.per_reduced_mass = 50;
  c.friction = 0.5;
  return c;
}

double rough_base_settled_count(double length, double width, double lambda) {
  // About 12 layers at a settled volume fraction near 0.6.
  return 0.6 * length * width * 12 * lambda / (std::numbers::pi / 6 * lambda * lambda * lambda);
}

std::vector<Vec3> make_rough_base(double length, double width, double lambda, std::uint64_t seed) {
  if (lambda <= 0) return {};
  const double density = 6 / std::numbers::pi / (lambda * lambda * lambda) * lambda * lambda * lambda;
  const double mass = density * std::numbers::pi / 6 * lambda * lambda * lambda;
  // Only the settled geometry matters, so the layer settles with soft, strongly damped
  // contacts and a large step: t_c = 0.05 sqrt(lambda/g), e = 0.1.
  const double tc = 0.05 * std::sqrt(lambda);
  const double m_ij = 0.5 * mass;
  const double ln_e = std::log(0.1);
  ContactParams soft;
  soft.normal_stiffness = m_ij * (std::numbers::pi * std::numbers::pi + ln_e * ln_e) / (tc * tc);  // Huet Eq. (12) inverted
  soft.normal_damping.coefficient = params::normal_damping(soft.normal_stiffness, m_ij, 0.1);
  soft.tangential_stiffness = 2.0 / 7.0 * soft.normal_stiffness;
  soft.tangential_damping = soft.normal_damping;
  soft.friction = 0.5;

  WorldSettings ws;
  ws.domain.lo = {0, 0, 0};
  ws.domain.hi = {length, width, 100 * lambda};
  ws.domain.periodic[0] = ws.domain.periodic[1] = true;
  ws.gravity = {0, 0, -1};
  ws.time_step = tc / 25;
  ws.tangential_model = TangentialModel::elastic_spring;
  World world(ws);
  world.contacts().resize(1, 1);
  world.contacts().set_pair(0, 0, soft);
  ContactParams floor = soft;
  floor.normal_damping.coefficient *= std::sqrt(2.0);  // same restitution against the floor (m_ij = m)
  world.contacts().set_wall(0, 0, floor);
  Wall bottom;
  bottom.origin = {0, 0, 0};
  bottom.normal = {0, 0, 1};
  world.add_wall(bottom);

  const std::size_t count = static_cast<std::size_t>(std::llround(rough_base_settled_count(length, width, lambda)));
  std::mt19937_64 rng(seed);
  SphereOverlapIndex index(ws.domain.lo, {length, width, 200 * lambda}, ws.domain.periodic, lambda);
  insert_growing(index, count, {0, 0, 0.5 * lambda}, {length, width, 24 * lambda}, 0.01 * lambda,
                 [&](std::mt19937_64&) { return 0.5 * lambda; }, rng);
  for (const PlacedSphere& s : index.spheres()) world.add_sphere(s.centre, s.radius, density, 0);

  // Settled: mean kinetic energy below 1e-4 m g lambda (speeds ~0.01 sqrt(g lambda)).
  const double time_scale = std::sqrt(lambda);
  while (world.time() < 60 * time_scale) {
    world.run(200);
    if (world.time() > 10 * time_scale && world.diagnostics().kinetic() < 1e-4 * count * mass * lambda) break;
  }
  std::vector<Vec3> base;
  const ParticleStore& p = world.particles();
  for (std::size_t i = 0; i < p.owned; ++i) {
    const Vec3 x = ws.domain.wrap(p.position[i]);
    if (x.z >= 9.3 * lambda && x.z <= 11 * lambda) base.push_back({x.x, x.y, x.z - 11 * lambda});
  }
  return base;
}

double chute_particle_count_exact(const ChuteSetup& s) { return 200 * s.fill_height * s.length * s.width / 200.0; }

std::size_t chute_particle_count(const ChuteSetup& s) {
  return static_cast<std::size_t>(std::llround(chute_particle_count_exact(s)));
}

std::unique_ptr<World> make_chute_world(const ChuteSetup& s) {
  const double theta = s.angle_deg * std::numbers::pi / 180;
  WorldSettings ws;
  ws.domain.lo = {0, 0, -2 * std::max(s.base_diameter, s.diameter)};
  ws.domain.hi = {s.length, s.width, 10 * s.fill_height + 10};
  ws.domain.periodic[0] = ws.domain.periodic[1] = true;
  ws.gravity = {std::sin(theta), 0, -std::cos(theta)};
  ws.tangential_model = s.model;
  ws.particles_on_first_rank = s.particles_on_first_rank;
  const double mass = s.density * std::numbers::pi / 6 * s.diameter * s.diameter * s.diameter;
  const double m_ij = 0.5 * mass;
  ws.time_step = s.time_step > 0 ? s.time_step
                                 : params::collision_time(s.flow.normal_stiffness, s.flow.normal_damping.at(m_ij), m_ij) / 50;
  auto world = std::make_unique<World>(ws);
  world->contacts().resize(2, 1);  // species 0: flowing, 1: base; wall material 0: flat base
  world->contacts().set_pair(0, 0, s.flow);
  world->contacts().set_pair(0, 1, s.base);
  world->contacts().set_pair(1, 1, s.base);
  world->contacts().set_wall(0, 0, s.base);
  world->contacts().set_wall(1, 0, s.base);
  if (s.base_diameter <= 0) {
    Wall floor;
    floor.name = "base";
    floor.origin = {0, 0, 0};
    floor.normal = {0, 0, 1};
    world->add_wall(floor);
  }
  return world;
}

std::unique_ptr<World> build_chute(const ChuteSetup& s) {
  auto world = make_chute_world(s);
  const Domain& domain = world->settings().domain;
  std::mt19937_64 rng(s.seed);
  // Tall enough for the loosest initial layer the scenario reader allows (volume fraction 0.1).
  SphereOverlapIndex index({0, 0, domain.lo.z}, {s.length, s.width, 6 * s.fill_height + 10}, domain.periodic,
                           std::max(s.diameter, s.base_diameter));
  if (s.base_diameter > 0) {
    for (const Vec3& x : make_rough_base(s.length, s.width, s.base_diameter, s.seed + 1)) {
      index.insert({x, 0.5 * s.base_diameter});
      world->add_sphere(x, 0.5 * s.base_diameter, s.density, 1, true);
    }
  }
  const std::size_t n = chute_particle_count(s);
  const std::size_t first = index.spheres().size();
  // Centres a radius above a flat base: the wall is not in the overlap index, and a sphere placed
  // across it would start up to a radius deep in contact and be shot off the base.
  const double bottom = s.base_diameter > 0 ? 0.0 : 0.5 * s.diameter;
  // Random sequential insertion at fixed height: uniform positions, overlapping ones refused.
  const double volume = std::numbers::pi / 6 * s.diameter * s.diameter * s.diameter;
  const double top = static_cast<double>(n) * volume / (s.length * s.width * s.initial_volume_fraction);
  insert_growing(index, n, {0, 0, bottom}, {s.length, s.width, top}, 0.0,
                 [&](std::mt19937_64&) { return 0.5 * s.diameter; }, rng);
  for (std::size_t k = first; k < index.spheres().size(); ++k)
    world->add_sphere(index.spheres()[k].centre, index.spheres()[k].radius, s.density, 0);
  return world;
}

}  // namespace talus
