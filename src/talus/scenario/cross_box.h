#pragma once
// Crosses of Huet et al. 2021 (Sec. III B, Table I) in an open-topped box: the set-up that the
// cross-pile benchmark and the pouring test share.
//   make_cross_box_world(setup)  : an empty World, Table I contacts, five walls (x-, x+, y-, y+,
//                                  floor: indices 0-4), the cross registered as shape 1
//   fill_cross_box(world, setup) : places setup.count crosses at random (dense, exact part tests,
//                                  insert_bodies_growing of body_insertion.h) from the floor up
#include <cstddef>
#include <cstdint>
#include <memory>

#include "talus/scenario/rigid_body_type.h"
#include "talus/world/world.h"

namespace talus {

struct CrossBoxSetup {
  std::size_t count = 1000;
  Vec3 box{0.2, 0.2, 0.05};      ///< m: floor size, and the height of the first insertion region
  Vec3 domain_hi{0.2, 0.2, 1.0}; ///< m: far corner of the domain (beyond the box for a flow)
  double crust = 1e-4;           ///< m: the scenario default, 5 % of the arm width
  double insert_growth = 5e-7;   ///< m the insertion region rises per rejected attempt (packing fraction ~0.07)
  double insert_clearance = 2e-4;///< m between placed crosses
  std::uint64_t seed = 1;
  bool manifold = true;          ///< up to 4 points per face contact (k/n each)
  bool narrow_phase_reuse = true;///< WorldSettings::narrow_phase_reuse
  double manifold_refit = 0;     ///< WorldSettings::manifold_refit
  double manifold_recycle = 0;   ///< WorldSettings::manifold_recycle
};

RigidBodyType huet_cross_type(double crust = 1e-4);
std::unique_ptr<World> make_cross_box_world(const CrossBoxSetup& setup);
// Returns the height of the highest cross centre.
double fill_cross_box(World& world, const CrossBoxSetup& setup);

// The equal-volume sphere radius of a Huet cross, the length its overlaps are measured against
// (Huet et al. 2021, Sec. III C: delta_max of about 1 % of it).
double huet_cross_equivalent_radius();

}  // namespace talus
