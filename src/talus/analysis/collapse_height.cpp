#include "talus/analysis/collapse_height.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace talus::collapse {

double quantile(std::vector<double> values, double q) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const double pos = std::clamp(q, 0.0, 1.0) * static_cast<double>(values.size() - 1);
  const std::size_t lo = static_cast<std::size_t>(std::floor(pos));
  const std::size_t hi = std::min(lo + 1, values.size() - 1);
  return values[lo] + (pos - static_cast<double>(lo)) * (values[hi] - values[lo]);
}

HeightProfile height_along_width(const ProjectionImage& top_view, double x_min, double x_max,
                                 double ground_z) {
  if (top_view.view != View::Top) throw std::invalid_argument("height_along_width: needs a top view");
  const ImageFrame& f = top_view.frame;
  int a0 = static_cast<int>(std::ceil((x_min - f.u_min) / f.pixel - 0.5));
  int a1 = static_cast<int>(std::floor((x_max - f.u_min) / f.pixel - 0.5));
  if (a1 < a0) a0 = a1 = static_cast<int>(std::floor((0.5 * (x_min + x_max) - f.u_min) / f.pixel));
  a0 = std::max(a0, 0);
  a1 = std::min(a1, top_view.nu - 1);

  HeightProfile p;
  p.y.resize(top_view.nv);
  p.h.assign(top_view.nv, 0.0);
  for (int b = 0; b < top_view.nv; ++b) {
    p.y[b] = top_view.v_centre(b);
    for (int a = a0; a <= a1; ++a) {
      if (top_view.occupied(a, b)) p.h[b] = std::max(p.h[b], top_view.top[top_view.index(a, b)] - ground_z);
    }
  }
  if (!p.h.empty()) p.mean = std::accumulate(p.h.begin(), p.h.end(), 0.0) / static_cast<double>(p.h.size());
  p.q1 = quantile(p.h, 0.25);
  p.median = quantile(p.h, 0.5);
  p.q3 = quantile(p.h, 0.75);
  return p;
}

}  // namespace talus::collapse
