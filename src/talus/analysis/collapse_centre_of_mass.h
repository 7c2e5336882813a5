#pragma once
// Displacement of the centre of mass of the whole pile, a less noisy measure of the collapse
// than the runout, which hangs on the few particles at the front. Huet et al. 2021, Appendix C.
#include "talus/analysis/snapshot.h"

namespace talus::collapse {

// Mass-weighted centre of the mobile (non-fixed) particles; zero when there are none.
Vec3 centre_of_mass(const Snapshot& snapshot);

struct CentreOfMassShift {
  Vec3 initial;             ///< m, centre of mass before the gate opens
  Vec3 final;               ///< m, centre of mass at rest
  Vec3 displacement;        ///< m, final - initial
  double dx_over_x0 = 0;    ///< (x_inf - x0) / x0, x measured from the back wall x = 0 (Fig. 24)
};

// x0 is the measured initial centre (L0/2 for a full rectangular column, as in Appendix C).
CentreOfMassShift centre_of_mass_shift(const Snapshot& initial, const Snapshot& final);

}  // namespace talus::collapse
