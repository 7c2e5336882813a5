#include "talus/scenario/cross_box.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "talus/contact/parameter_procedure.h"
#include "talus/scenario/body_insertion.h"

namespace talus {

namespace {
constexpr int kCrossShape = 1;  // the first shape after the sphere
}

RigidBodyType huet_cross_type(double crust) {
  return make_rigid_body_type(make_huet_cross(27e-3, 2e-3, 3e-3, crust), 770);  // Sec. III B, Table I
}

double huet_cross_equivalent_radius() {
  return std::cbrt(3 * huet_cross_type().volume / (4 * std::numbers::pi));
}

std::unique_ptr<World> make_cross_box_world(const CrossBoxSetup& setup) {
  const RigidBodyType type = huet_cross_type(setup.crust);
  WorldSettings s;
  const double margin = 0.05;
  s.domain = {{-margin, -margin, -margin}, setup.domain_hi + Vec3{margin, margin, margin}};
  s.time_step = 2.5e-6;  // Huet et al. 2021, Table I
  s.contact_manifold = setup.manifold;
  s.narrow_phase_reuse = setup.narrow_phase_reuse;
  s.manifold_refit = setup.manifold_refit;
  s.manifold_recycle = setup.manifold_recycle;
  auto w = std::make_unique<World>(s);
  ContactParams c;  // Huet et al. 2021, Table I
  c.normal_stiffness = 4.5e5;
  c.normal_damping.coefficient = params::normal_damping(c.normal_stiffness, 0.5 * type.mass, 0.85);
  c.tangential_stiffness = 300;
  c.tangential_damping.per_reduced_mass = 2 * 1e3;  // gamma_t = eta_t / (2 m_ij) = 1e3 1/s (seeds README)
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
    wl.origin[k / 2] = (k % 2 == 0) ? 0 : setup.box[k / 2];
    w->add_wall(wl);
  }
  w->add_shape(type.shape);
  return w;
}

double fill_cross_box(World& world, const CrossBoxSetup& setup) {
  const RigidBodyType type = huet_cross_type(setup.crust);
  std::mt19937_64 rng(setup.seed);
  BodyOverlapIndex index(type.radius);
  const PlacedBody prototype{{}, {}, &type.shape, type.radius};
  const std::vector<PlacedBody> bodies = insert_bodies_growing(index, prototype, setup.count, {0, 0, 0}, setup.box,
                                                               setup.insert_growth, setup.insert_clearance, rng, 1e300);
  double top = 0;
  world.reserve_particles(world.owned_count() + bodies.size());
  for (const PlacedBody& b : bodies) {
    world.add_particle(rigid_particle(type, kCrossShape, b.position, b.orientation, 0));
    top = std::max(top, b.position.z);
  }
  return top;
}

}  // namespace talus
