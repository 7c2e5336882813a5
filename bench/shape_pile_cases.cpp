#include "shape_pile_cases.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "talus/contact/parameter_procedure.h"
#include "talus/scenario/body_insertion.h"
#include "talus/shape/convex_hull.h"
#include "talus/shape/named_shapes.h"

namespace talus::bench {

namespace {

constexpr int kBodyShape = 1;  // the first shape after the sphere

// A regular icosahedron's 12 corners, (0, +-1, +-phi) and their cyclic permutations, scaled to
// the circumradius (m).
std::vector<Vec3> icosahedron_corners(double circumradius) {
  const double phi = 0.5 * (1 + std::sqrt(5.0));
  const double s = circumradius / std::sqrt(1 + phi * phi);
  std::vector<Vec3> v;
  for (double a : {-1.0, 1.0})
    for (double b : {-phi, phi}) {
      v.push_back(Vec3{0, a, b} * s);
      v.push_back(Vec3{a, b, 0} * s);
      v.push_back(Vec3{b, 0, a} * s);
    }
  return v;
}

// As a "polyhedron" species of a scenario file: crust 5 % of the inradius (shape_reader.h).
CompositeShape icosahedron(double circumradius) {
  const std::vector<Vec3> corners = icosahedron_corners(circumradius);
  double inradius = std::numeric_limits<double>::infinity();
  for (const HullFace& f : build_convex_hull(corners).faces) inradius = std::min(inradius, f.offset);
  CompositeShape c;
  c.add(make_polyhedron(corners, 0.05 * inradius), Pose{});
  return c;
}

// A [contact] table of model = "memory" with restitution_damping = "eq11": eta_n from Huet et
// al. 2021, Eq. (17), in sqrt(m_ij); tangential_damping_factor gamma_t = eta_t / (2 m_ij).
ContactParams memory_contact(double kn, double restitution, double kt, double damping_factor, double friction) {
  ContactParams c;
  c.normal_stiffness = kn;
  c.normal_damping.per_sqrt_reduced_mass = params::normal_damping(kn, 1.0, restitution);
  c.tangential_stiffness = kt;
  c.tangential_damping.per_reduced_mass = 2 * damping_factor;
  c.friction = friction;
  c.clamp = NormalClamp::clamped;  // as the reader sets it for "memory" (Huet et al. 2021, Eq. 5)
  return c;
}

ContactParams with_friction(ContactParams c, double friction) {
  c.friction = friction;
  return c;
}

}  // namespace

std::vector<ShapePileCase> shape_pile_cases() {
  // Huet et al. 2021, Table I (examples/dam_break_hexapods.toml) and Table II
  // (examples/hopper_tetrapods.toml).
  const ContactParams table1 = memory_contact(4.5e5, 0.85, 300, 1e3, 0.46);
  const ContactParams table2 = memory_contact(7.34e5, 0.45, 2.26e5, 4e4, 0.4);
  std::vector<ShapePileCase> cases(3);
  // Settling times: by then the mean speed is 0.2-2 mm/s, the fastest body (a rattler on top)
  // under 5-10 cm/s and the contact count levels off. Flow times: about sqrt(d/g) of the body
  // (0.05 s for 2.7 cm, 0.02 s for the 4 mm tetrapods), as the cross pile's 0.05 s.

  ShapePileCase& ico = cases[0];
  ico.name = "icosahedra";
  ico.type = make_rigid_body_type(icosahedron(5e-3), 770);
  ico.pair = table1;
  ico.wall = with_friction(table1, 0.62);
  ico.time_step = 2.5e-6;
  ico.manifold = true;
  ico.box = {0.1, 0.1, 0.05};
  ico.domain_height = 0.5;
  ico.insert_growth = 5e-7;  // a cloud of solid fraction 0.27, up to 11 cm
  ico.settle_time = 0.3;
  ico.flow_time = 0.05;

  ShapePileCase& hex = cases[1];
  hex.name = "hexapods";
  hex.type = make_rigid_body_type(make_hexapod(0.027, 0.003, 0.05 * hexapod_smallest_half(0.003)), 770);
  hex.pair = table1;
  hex.wall = with_friction(table1, 0.62);
  hex.time_step = 2.5e-6;
  hex.manifold = true;
  hex.box = {0.2, 0.2, 0.05};
  hex.domain_height = 1.0;
  // dam_break_hexapods.toml's fill_growth: solid fraction 0.08, up to 21 cm (hexapods placed at
  // random jam near 0.09, however slowly the region grows).
  hex.insert_growth = 1e-6;
  hex.settle_time = 0.35;
  hex.flow_time = 0.05;

  ShapePileCase& tet = cases[2];
  tet.name = "tetrapods";
  tet.type = make_rigid_body_type(make_tetrapod(0.002, 0.0005, 0.05 * tetrapod_smallest_half(0.002, 0.0005)), 2500);
  tet.pair = table2;
  tet.wall = with_friction(table2, 0.45);
  tet.time_step = 5e-7;
  tet.manifold = false;
  tet.box = {0.03, 0.03, 0.01};
  tet.domain_height = 0.15;
  tet.insert_growth = 1e-7;  // solid fraction 0.16, up to 3.7 cm
  tet.settle_time = 0.1;
  tet.flow_time = 0.02;
  return cases;
}

std::unique_ptr<World> make_shape_pile_world(const ShapePileCase& c) {
  WorldSettings s;
  const double margin = 0.25 * c.box.x;
  s.domain = {{-margin, -margin, -margin}, Vec3{5 * c.box.x, c.box.y, c.domain_height} + Vec3{margin, margin, margin}};
  s.time_step = c.time_step;
  s.contact_manifold = c.manifold;
  auto w = std::make_unique<World>(s);
  w->contacts().resize(1, 1);
  w->contacts().set_pair(0, 0, c.pair);
  w->contacts().set_wall(0, 0, c.wall);
  const char* names[5] = {"x-", "x+", "y-", "y+", "floor"};
  for (int k = 0; k < 5; ++k) {
    Wall wl;
    wl.name = names[k];
    wl.normal = {};
    wl.normal[k / 2] = (k % 2 == 0) ? 1 : -1;
    wl.origin[k / 2] = (k % 2 == 0) ? 0 : c.box[k / 2];
    w->add_wall(wl);
  }
  w->add_shape(c.type.shape);
  return w;
}

double fill_shape_pile(World& world, const ShapePileCase& c, std::size_t count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  BodyOverlapIndex index(c.type.radius);
  const PlacedBody prototype{{}, {}, &c.type.shape, c.type.radius};
  // A small clearance keeps the first contacts gentle, as the scenario's dam-break fill.
  const double clearance = 1e-3 * c.type.radius;
  const std::vector<PlacedBody> bodies = insert_bodies_growing(index, prototype, count, {0, 0, 0}, c.box,
                                                               c.insert_growth, clearance, rng, c.domain_height);
  double top = 0;
  world.reserve_particles(world.owned_count() + bodies.size());
  ParticleInit p = rigid_particle(c.type, kBodyShape, {}, {}, 0);
  for (const PlacedBody& b : bodies) {  // placed by the principal frame the World steps
    p.position = b.position;
    p.orientation = b.orientation;
    world.add_particle(p);
    top = std::max(top, b.position.z);
  }
  return top;
}

}  // namespace talus::bench
