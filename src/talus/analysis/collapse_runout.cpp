#include "talus/analysis/collapse_runout.h"

#include <stdexcept>

namespace talus::collapse {

IntensityProfile column_intensity(const ProjectionImage& top_view) {
  if (top_view.view != View::Top) throw std::invalid_argument("column_intensity: needs a top view");
  IntensityProfile profile;
  profile.pixel = top_view.frame.pixel;
  profile.x.resize(top_view.nu);
  profile.intensity.resize(top_view.nu);
  for (int a = 0; a < top_view.nu; ++a) {
    int filled = 0;
    for (int b = 0; b < top_view.nv; ++b) filled += top_view.occupied(a, b) ? 1 : 0;
    profile.x[a] = top_view.u_centre(a);
    profile.intensity[a] = top_view.nv > 0 ? static_cast<double>(filled) / top_view.nv : 0.0;
  }
  return profile;
}

double runout_at_threshold(const IntensityProfile& profile, double threshold) {
  if (profile.x.empty()) return 0.0;
  const double half = 0.5 * profile.pixel;
  // Leading columns below the threshold (a frame that starts before the back wall) are not
  // the pile's end: the scan starts at the first column that reaches the threshold.
  std::size_t a = 0;
  while (a < profile.x.size() && profile.intensity[a] < threshold) ++a;
  if (a == profile.x.size()) return profile.x.front() - half;
  for (; a < profile.x.size(); ++a) {
    if (profile.intensity[a] < threshold) return profile.x[a] - half;
  }
  return profile.x.back() + half;
}

Runout measure_runout(const ProjectionImage& top_view, const RunoutThresholds& thresholds) {
  Runout r;
  r.profile = column_intensity(top_view);
  r.nominal = runout_at_threshold(r.profile, thresholds.nominal);
  r.low = runout_at_threshold(r.profile, thresholds.low);
  r.high = runout_at_threshold(r.profile, thresholds.high);
  const double far_edge = r.profile.x.empty() ? 0.0 : r.profile.x.back() + 0.5 * r.profile.pixel;
  r.reached_frame_end = r.high >= far_edge;
  return r;
}

}  // namespace talus::collapse
