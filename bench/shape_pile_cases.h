#pragma once
// The three piles of the shape benchmark (shape_pile.h), each of one body shape in an
// open-topped box of five walls (x-, x+, y-, y+, floor: indices 0-4), the domain reaching past
// x+ for the flow once that wall goes:
//   icosahedra : regular icosahedra of circumradius 5 mm (317 mm^3, about a Huet cross's
//                312 mm^3), density 770 and Table I contacts of Huet et al. 2021 as the cross
//                pile, dt = 2.5e-6 s, on a 10 x 10 cm floor;
//   hexapods   : the hexapods of examples/dam_break_hexapods.toml (three 27 x 3 x 3 mm rods,
//                770 kg/m^3, Table I, face manifolds), dt = 2.5e-6 s, on a 20 x 20 cm floor;
//   tetrapods  : the tetrapods of examples/hopper_tetrapods.toml (arms 2 mm long, 0.5 mm in
//                radius, 2500 kg/m^3, Table II), dt = 5e-7 s, on a 3 x 3 cm floor.
// Settled, 1000 bodies stand about 5 cm deep (icosahedra, solid fraction 0.59, 5 bodies),
// 8 cm (hexapods, 0.19, 3 bodies) and 1.7 cm (tetrapods, 0.36, 4 bodies). Shapes and crusts
// are the scenario reader's (shape/named_shapes.h; the icosahedron's crust is 5 % of its
// inradius as for a "polyhedron" species), contacts are the examples' [contact] tables.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "talus/scenario/rigid_body_type.h"
#include "talus/world/world.h"

namespace talus::bench {

struct ShapePileCase {
  std::string name;              ///< METRIC infix: "icosahedra", "hexapods" or "tetrapods"
  RigidBodyType type;
  ContactParams pair, wall;      ///< body-body, body-wall
  double time_step = 0;          ///< s
  bool manifold = false;         ///< face and edge contacts as manifolds of up to 4 points
  Vec3 box;                      ///< m: floor size, and the height of the first insertion region
  double domain_height = 0;      ///< m
  double insert_growth = 0;      ///< m the insertion region rises per rejected placement
  double settle_time = 0;        ///< s simulated from the placed cloud to the timed static pile
  double flow_time = 0;          ///< s from the removal of the x+ wall to the timed flow
};

std::vector<ShapePileCase> shape_pile_cases();

// An empty World: the case's settings, contacts, walls, and its body as shape 1.
std::unique_ptr<World> make_shape_pile_world(const ShapePileCase& c);
// Places `count` bodies at random (dense, exact part tests: insert_bodies_growing of
// body_insertion.h) from the floor up; returns the height of the highest centre.
double fill_shape_pile(World& world, const ShapePileCase& c, std::size_t count, std::uint64_t seed);

}  // namespace talus::bench
