#include "cross_pile.h"

#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <string>

#include "talus/contact/parameter_procedure.h"
#include "talus/scenario/insertion.h"
#include "talus/scenario/rigid_body_type.h"
#include "talus/world/world.h"

namespace talus::bench {

namespace {

constexpr double kBox = 0.2;  // m, square floor

std::unique_ptr<World> pour_pile(const CrossPileOptions& o, const RigidBodyType& type) {
  WorldSettings s;
  s.domain = {{0, 0, 0}, {kBox, kBox, 3.0}};
  s.time_step = 2.5e-6;  // Huet et al. 2021, Table I
  s.contact_manifold = true;
  auto w = std::make_unique<World>(s);
  ContactParams c;  // Huet et al. 2021, Table I
  c.normal_stiffness = 4.5e5;
  c.normal_damping.coefficient = params::normal_damping(c.normal_stiffness, 0.5 * type.mass, 0.85);
  c.tangential_stiffness = 300;
  c.tangential_damping.per_reduced_mass = 2 * 1e3;  // gamma_t = eta_t / (2 m_ij) = 1e3 1/s
  c.friction = 0.46;
  ContactParams wall = c;
  wall.normal_damping.coefficient = params::normal_damping(c.normal_stiffness, type.mass, 0.85);
  wall.friction = 0.62;
  w->contacts().resize(1, 1);
  w->contacts().set_pair(0, 0, c);
  w->contacts().set_wall(0, 0, wall);
  const char* names[5] = {"x-", "x+", "y-", "y+", "floor"};
  for (int k = 0; k < 5; ++k) {
    Wall wl;
    wl.name = names[k];
    wl.normal = {};
    wl.normal[k / 2] = (k % 2 == 0) ? 1 : -1;
    wl.origin[k / 2] = (k % 2 == 0) ? 0 : kBox;
    w->add_wall(wl);
  }
  const int shape = w->add_shape(type.shape);
  std::mt19937_64 rng(1);
  const bool closed[3] = {false, false, false};
  SphereOverlapIndex index({0, 0, 0}, {kBox, kBox, 3.0}, closed, 2 * type.radius);
  const double r = type.radius;
  insert_growing(index, o.crosses, {r, r, r}, {kBox - 2 * r, kBox - 2 * r, 0.05}, 1e-4, [&](std::mt19937_64&) { return r; },
                 rng, 2.9);
  std::normal_distribution<double> g(0, 1);
  for (const PlacedSphere& p : index.spheres())
    w->add_particle(rigid_particle(type, shape, p.centre, Quat{g(rng), g(rng), g(rng), g(rng)}.normalized(), 0));
  while (w->time() < o.settle_time_limit) {
    w->run(2000);
    const Diagnostics d = w->diagnostics();
    std::fprintf(stderr, "[crosspile] t = %.3f s  largest speed %.3g m/s  contacts %zu\n", w->time(), d.max_speed,
                 d.contacts + d.wall_contacts);
    if (w->time() > 0.2 && d.max_speed < o.settle_speed) break;
  }
  return w;
}

double time_steps(World& w, int threads, std::uint64_t steps) {
  omp_set_num_threads(threads);
  w.run(20);
  const auto start = std::chrono::steady_clock::now();
  w.run(steps);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return s * 1e6 / static_cast<double>(steps * w.owned_count());
}

}  // namespace

void run_cross_pile(const CrossPileOptions& o, void (*metric)(const char*, double, const char*)) {
  const RigidBodyType type = make_rigid_body_type(make_huet_cross(27e-3, 2e-3, 3e-3, 1e-4), 770);
  const int threads = omp_get_max_threads();
  const auto start = std::chrono::steady_clock::now();
  auto w = pour_pile(o, type);
  metric("crosspile_settle_seconds", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), "s");
  metric("crosspile_particles", static_cast<double>(w->owned_count()), "count");
  const Diagnostics settled = w->diagnostics();
  metric("crosspile_contacts_per_particle", 2.0 * static_cast<double>(settled.contacts) / w->owned_count(), "count");
  metric("crosspile_wall_contacts_per_particle", static_cast<double>(settled.wall_contacts) / w->owned_count(), "count");
  metric("crosspile_max_overlap_over_radius", settled.max_overlap_ratio, "ratio");
  w->timer_mutable().reset();
  metric("crosspile_static_1t", time_steps(*w, 1, o.steps), "us");
  metric("crosspile_static_2t", time_steps(*w, 2, o.steps), "us");
  const PhaseTimer& t = w->timer();
  const double total = t.seconds(Phase::integrate) + t.seconds(Phase::neighbors) + t.seconds(Phase::pair_forces) +
                       t.seconds(Phase::wall_forces);
  metric("crosspile_share_pair_forces", 100 * t.seconds(Phase::pair_forces) / total, "%");
  metric("crosspile_share_wall_forces", 100 * t.seconds(Phase::wall_forces) / total, "%");
  metric("crosspile_share_neighbors", 100 * t.seconds(Phase::neighbors) / total, "%");
  metric("crosspile_share_integrate", 100 * t.seconds(Phase::integrate) / total, "%");
  // Flowing: the x+ wall goes, the pile slumps out of the box.
  Wall& side = w->walls_mutable()[1];
  side.motion.kind = WallMotion::Kind::removed;
  side.motion.start_time = w->time();
  omp_set_num_threads(threads);
  w->run(4000);
  metric("crosspile_flow_1t", time_steps(*w, 1, o.steps), "us");
  metric("crosspile_flow_2t", time_steps(*w, 2, o.steps), "us");
  metric("crosspile_flow_mean_speed", w->diagnostics().mean_speed, "m/s");
  omp_set_num_threads(threads);
}

}  // namespace talus::bench
