#pragma once
// Spheres poured into a closed box settle under gravity (Huet et al. 2021, Appendix B 1,
// Fig. 22): with the memory contact model they reach a true static state.
#include <cstdint>
#include <memory>

#include "talus/contact/contact_law.h"
#include "talus/world/world.h"

namespace talus {

struct SettlingBoxSetup {
  std::size_t count = 750;
  double radius = 1e-3;               ///< m
  double density = 2500;              ///< kg/m^3
  Vec3 box{0.016, 0.016, 0.06};       ///< m, inner size; the floor at z = 0
  double restitution = 0.45;          ///< e_n (Huet et al. 2021, Table II)
  double max_overlap = 0.05;          ///< delta_max / R at 1 m/s (Eq. 16), softer than Table II for a larger step
  double friction = 0.5;              ///< mu_c, particle-particle
  double wall_friction = 0.45;        ///< mu_c, particle-wall (Table II)
  double rolling_friction = 0.45;     ///< mu_r, particle-particle (Table II)
  double wall_rolling_friction = 0.1; ///< mu_r, particle-wall (Table II)
  TangentialModel model = TangentialModel::memory;
  double steps_per_contact = 20;      ///< Huet et al. 2021, Sect. II C 1
  std::uint64_t seed = 1;
};

std::unique_ptr<World> build_settling_box(const SettlingBoxSetup& s);

}  // namespace talus
