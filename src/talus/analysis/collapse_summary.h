#pragma once
// Everything a dam-break run reports, from its state before the gate opens and at rest:
// runout, heights, centre-of-mass shift, the nondimensional numbers of Figs. 10, 11 and 24 of
// Huet et al. 2021, and the regime. Geometry: the column fills x in [0, L0] against the back
// wall x = 0, the gate is at x = L0, the box spans y in [0, W], gravity is along -z.
#include <vector>

#include "talus/analysis/collapse_centre_of_mass.h"
#include "talus/analysis/collapse_footprint.h"
#include "talus/analysis/collapse_height.h"
#include "talus/analysis/collapse_regime.h"
#include "talus/analysis/collapse_runout.h"

namespace talus::collapse {

struct CollapseSetup {
  double initial_length = 0;   ///< m, L0: gate position
  double box_length = 0;       ///< m, L: the top view spans x in [0, L]
  double width = 0;            ///< m, W
  double particle_size = 0;    ///< m, d (e.g. circumscribed diameter): scale of the tolerances
  double pixel = 0.43e-3;      ///< m, Huet et al. 2021, Sec. III C
  double height_band = 0;      ///< m, heights are read on x in [0, band]; 0 means one particle size
  RunoutThresholds thresholds;
  RegimeTolerances tolerances;
};

struct CollapseMeasures {
  Runout runout;                    ///< of the final state
  HeightProfile initial_height;     ///< H0 = initial_height.mean
  HeightProfile final_height;       ///< H_inf = final_height.mean
  CentreOfMassShift centre_of_mass;
  double aspect_ratio = 0;          ///< H0 / L0
  double runout_ratio = 0;          ///< (L_inf - L0) / L0, Fig. 10
  double runout_ratio_low = 0;      ///< same at the 20 % threshold
  double runout_ratio_high = 0;     ///< same at the 1 % threshold
  double height_ratio = 0;          ///< H0 / H_inf, Fig. 11
  double height_ratio_low = 0;      ///< H0 / q3(H_inf)
  double height_ratio_high = 0;     ///< H0 / q1(H_inf)
  double centre_ratio = 0;          ///< dx / x0, Fig. 24
  RegimeReport regime;
};

// Footprints are index-aligned with each snapshot's particles (see collapse_footprint.h).
CollapseMeasures measure_collapse(const Snapshot& initial, const std::vector<Footprint>& initial_footprints,
                                  const Snapshot& final, const std::vector<Footprint>& final_footprints,
                                  const CollapseSetup& setup);

}  // namespace talus::collapse
