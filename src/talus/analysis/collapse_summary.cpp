#include "talus/analysis/collapse_summary.h"

#include <stdexcept>

namespace talus::collapse {
namespace {

double ratio(double a, double b) { return b != 0 ? a / b : 0.0; }

}  // namespace

CollapseMeasures measure_collapse(const Snapshot& initial, const std::vector<Footprint>& initial_footprints,
                                  const Snapshot& final, const std::vector<Footprint>& final_footprints,
                                  const CollapseSetup& setup) {
  if (!(setup.initial_length > 0) || !(setup.box_length > 0) || !(setup.width > 0) || !(setup.particle_size > 0)) {
    throw std::invalid_argument("measure_collapse: L0, L, W and particle size must be positive");
  }
  const ImageFrame frame{0.0, setup.box_length, 0.0, setup.width, setup.pixel};
  const double band = setup.height_band > 0 ? setup.height_band : setup.particle_size;
  const double L0 = setup.initial_length;

  CollapseMeasures m;
  const ProjectionImage before = rasterise(initial_footprints, View::Top, frame);
  const ProjectionImage after = rasterise(final_footprints, View::Top, frame);
  m.runout = measure_runout(after, setup.thresholds);
  m.initial_height = height_along_width(before, 0.0, band);
  m.final_height = height_along_width(after, 0.0, band);
  m.centre_of_mass = centre_of_mass_shift(initial, final);

  const double H0 = m.initial_height.mean;
  m.aspect_ratio = H0 / L0;
  m.runout_ratio = (m.runout.nominal - L0) / L0;
  m.runout_ratio_low = (m.runout.low - L0) / L0;
  m.runout_ratio_high = (m.runout.high - L0) / L0;
  m.height_ratio = ratio(H0, m.final_height.mean);
  m.height_ratio_low = ratio(H0, m.final_height.q3);
  m.height_ratio_high = ratio(H0, m.final_height.q1);
  m.centre_ratio = m.centre_of_mass.dx_over_x0;
  m.regime = classify_regime(initial, final,
                             {L0, H0, m.runout.nominal, m.final_height.mean, setup.particle_size},
                             setup.tolerances);
  return m;
}

}  // namespace talus::collapse
