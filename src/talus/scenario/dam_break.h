#pragma once
// The dam-break collapse of Huet et al. 2021, Sec. III: a box L x H x W with a gate at x = L0,
// a column of particles filled behind the gate at random positions and orientations, left to
// settle, then the gate opens (removed at once, or pulled up at 43 m/s^2 to 3 m/s with
// particle-gate friction: the "gate effect" of Figs. 6-7) and the column collapses.
//
// [dam_break] builds the box, the gate and the filling from a few lengths, so a sweep over L0
// or the particle count is one --set. The phases and measurements are a RunObserver
// (dam_break_observer.h).
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <string>

#include "talus/io/scenario_file.h"
#include "talus/shape/composite_shape.h"
#include "talus/world/world.h"

namespace talus {

struct DamBreakSetup {
  double box_length = 0.64;     ///< m, L (Huet et al. 2021, Sec. III A)
  double box_height = 0.30;     ///< m, H: walls and gate reach the top of the domain, above it
  double width = 0.20;          ///< m, W = W0, the column spans the channel
  double gate_position = 0.04;  ///< m, L0 (4, 8, 12, 20 or 30 cm in the paper)
  double domain_height = 1.0;   ///< m, room for the filling cloud
  std::string species;          ///< particles of the column
  std::size_t count = 0;        ///< particles in the column
  double fill_height = 0.1;     ///< m, first height of the filling region (it grows when full)
  double fill_growth = 1e-4;    ///< m per rejected placement
  bool gate_pulled = true;      ///< false: removed at once
  double gate_acceleration = 43;  ///< m/s^2
  double gate_top_speed = 3;    ///< m/s
  double static_speed = 1e-3;   ///< m/s: the column is static once no particle is faster
  double static_mean_speed = std::numeric_limits<double>::infinity();  ///< m/s: ... and the mean speed is below
  double settle_min_time = 0.05;  ///< s, before the static test
  double settle_max_time = 3;   ///< s: the gate opens then even if the column still moves
  double stop_speed = 5e-3;     ///< m/s: the collapse is over once no particle is faster
  double stop_mean_speed = std::numeric_limits<double>::infinity();  ///< m/s: ... and the mean speed is below
  double collapse_min_time = 0.1; ///< s after the gate opened, before the stop test
  double pixel = 0.43e-3;       ///< m, top-view pixel (Sec. III C camera)
  // The tangential history rule from the gate's opening on; empty: contact.tangential's all
  // along. Huet et al. 2021, Fig. 19 collapses the same settled column with and without memory.
  std::optional<TangentialModel> collapse_tangential;
};

// Reads [dam_break]; species are checked by the caller.
DamBreakSetup read_dam_break(const io::ScenarioFile& file);

// The simulation box [0, L] x [0, W] x [0, domain_height], not periodic.
Domain dam_break_domain(const DamBreakSetup& setup);

// Indices of the walls the analyses need.
struct DamBreakWalls {
  int floor = -1, back = -1, end = -1, side_lo = -1, side_hi = -1, gate = -1;
};

// Floor, back wall x = 0, end wall x = L, side walls y = 0 and y = W, and the gate at x = L0
// facing the column (closed until the observer opens it).
DamBreakWalls add_dam_break_walls(World& world, const DamBreakSetup& setup, int material);

// Places the column's particles at random non-overlapping positions and orientations behind the
// gate (by their true shapes: body_insertion.h). `shape` is null for spheres.
void fill_dam_break(World& world, const DamBreakSetup& setup, const ParticleInit& prototype,
                    const CompositeShape* shape, std::mt19937_64& rng);

}  // namespace talus
