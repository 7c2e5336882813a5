#pragma once
// The periodic chute of Weinhart et al. 2012, Sect. 5: spheres of diameter d = 1, mass m = 1,
// g = 1 flowing over a rough base of fixed spheres of diameter lambda, gravity tilted by theta.
#include <cstdint>
#include <memory>
#include <vector>

#include "talus/contact/contact_params.h"
#include "talus/world/world.h"

namespace talus {

struct ChuteSetup {
  double length = 20;           ///< x extent (periodic)
  double width = 10;            ///< y extent (periodic)
  double base_diameter = 1;     ///< lambda; 0 gives a flat wall
  double fill_height = 20;      ///< H: about 200 H particles per 20 x 10 of area
  double angle_deg = 24;        ///< theta
  // The poured layer's volume fraction before it falls (Weinhart et al. 2012, Sect. 5: "about
  // 0.3", which gives the layer the kinetic energy to start flowing as it compacts to H). The
  // paper's rule of raising the box by 0.01 d per rejected insertion would give about 0.15 at
  // the bottom and less above, a column four times H: its lower part then settles and may arrest
  // before the rest has landed, so a thick layer is built on a bed already at rest.
  double initial_volume_fraction = 0.3;
  double diameter = 1;          ///< d of the flowing particles
  double density = 6 / 3.14159265358979323846;  ///< m = 1 for d = 1
  ContactParams flow;           ///< flow-flow contacts
  ContactParams base;           ///< flow-base (and flow-wall) contacts
  TangentialModel model = TangentialModel::elastic_spring;
  double time_step = 0;         ///< 0: t_c / 50 (Weinhart et al. 2012, Sect. 2)
  std::uint64_t seed = 1;
  bool particles_on_first_rank = false;  ///< WorldSettings::particles_on_first_rank
};

// Weinhart et al. 2012, Sect. 5 parameters: k_n = 2e5, gamma_n = 50 (per unit reduced mass, the
// Silbert convention), k_t = 2/7 k_n, gamma_t = gamma_n, mu_c = 1/2.
ContactParams weinhart_chute_contact();

// Weinhart et al. 2012, Sect. 5: settle a layer about 12 lambda thick on a flat floor, keep the
// particles with z in [9.3, 11] lambda and move them down by 11 lambda.
std::vector<Vec3> make_rough_base(double length, double width, double lambda, std::uint64_t seed);

// Spheres make_rough_base settles, before it keeps a slice of them (a double: the scenario
// reader compares it with its particle limit before anything is built).
double rough_base_settled_count(double length, double width, double lambda);

// Number of flowing particles for filling height H: 200 H per 20 x 10 of area, rounded.
std::size_t chute_particle_count(const ChuteSetup& s);
// The same unrounded, for the reader's particle limit.
double chute_particle_count_exact(const ChuteSetup& s);

// The chute's World without particles: periodic box, tilted gravity, time step, contact table
// (species 0 flowing, 1 base), and a flat floor when lambda = 0.
std::unique_ptr<World> make_chute_world(const ChuteSetup& s);

// Builds the chute, fills it by growing-region insertion and tilts gravity.
std::unique_ptr<World> build_chute(const ChuteSetup& s);

}  // namespace talus
