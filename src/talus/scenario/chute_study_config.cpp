// [chute.flow_state] and [chute.coarse_graining] of a scenario file.
#include <algorithm>
#include <cmath>

#include "talus/io/number_format.h"
#include "talus/scenario/chute_study.h"

namespace talus {

ChuteStudyConfig read_chute_study(const io::ScenarioFile& f, double contact_time, double end_time, double fill_height,
                                  double base_diameter, double particle_density) {
  ChuteStudyConfig c;
  c.particle_density = particle_density;
  const std::string fs = "chute.flow_state.";
  FlowStateCriteria& k = c.criteria;
  k.arrest_ratio = f.get_or<double>(fs + "arrest_ratio", k.arrest_ratio, io::positive);
  k.arrest_time = f.get_or<double>(fs + "arrest_time", k.arrest_time, io::positive);
  k.window_fraction = f.get_or<double>(fs + "window_fraction", k.window_fraction, io::in_range(0, 1));
  k.min_window = f.get_or<double>(fs + "min_window", k.min_window, io::positive);
  k.drift_tolerance = f.get_or<double>(fs + "drift_tolerance", k.drift_tolerance, io::positive);
  k.oscillation_tolerance = f.get_or<double>(fs + "oscillation_tolerance", k.oscillation_tolerance, io::positive);
  k.layering_tolerance = f.get_or<double>(fs + "layering_tolerance", k.layering_tolerance, io::positive);
  c.stop_when_arrested = f.get_or<bool>(fs + "stop_when_arrested", false);

  c.coarse_grain = f.has("chute.coarse_graining");
  const std::string cg = "chute.coarse_graining.";
  c.start = f.get_or<double>(cg + "start", 0.5 * end_time, io::non_negative);
  c.end = f.get_or<double>(cg + "end", end_time, io::positive);
  if (c.coarse_grain && c.end <= c.start) f.fail(cg + "end", "must be after chute.coarse_graining.start");
  c.interval = f.get_or<double>(cg + "interval", 0.5 * contact_time, io::positive);  // Weinhart et al. 2012, Sect. 7
  c.series_interval = f.get_or<double>(cg + "series_interval", 1.0, io::positive);
  const std::string kernel = f.get_choice_or(cg + "function", "gaussian", {"gaussian", "lucy"});
  c.kernel = kernel == "lucy" ? CgKernel::lucy : CgKernel::gaussian;
  c.width = f.get_or<double>(cg + "width", 0.25, io::positive);
  c.extra_widths = f.get_or<std::vector<double>>(cg + "extra_widths", {}, io::positive);
  // The base's fixed spheres sit in z in [-1.7 lambda, 0] (Sect. 5) and the basal contacts
  // within half a diameter of z = 0; the profile starts a cutoff below them, so that the whole
  // base force density (and with it the weight of the flow) is on the grid. H compacts to about
  // 0.9 H; saltating grains fly above.
  const double cutoff = c.kernel == CgKernel::lucy ? c.width : 3 * c.width;
  c.z_min = f.get_or<double>(cg + "z_min", -std::max(base_diameter, c.diameter) - cutoff);
  c.z_max = f.get_or<double>(cg + "z_max", 1.2 * fill_height + 5);
  if (c.coarse_grain && c.z_max <= c.z_min) f.fail(cg + "z_max", "must be above chute.coarse_graining.z_min");
  // Four points per width resolve the Gaussian and keep the balance's finite differences accurate.
  const double fine = std::ceil((c.z_max - c.z_min) / (0.25 * c.width)) + 1;
  // Compared as a double: the count may not fit an int (z_max = 1e300).
  if (c.coarse_grain && !f.has(cg + "points") && !(fine <= 1e6))
    f.fail(cg + "z_max", "the profile from z_min to z_max would need " + io::format_double(fine) +
                             " points, a quarter width apart (at most 1e6): give chute.coarse_graining.points");
  const int fallback = fine <= 1e6 ? static_cast<int>(std::max(fine, 3.0)) : 1000000;  // unused without coarse graining
  c.points = f.get_or<int>(cg + "points", fallback, io::in_range(3, 1e6));
  return c;
}

}  // namespace talus
