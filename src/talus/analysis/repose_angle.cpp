#include "talus/analysis/repose_angle.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace talus::repose {

namespace {

bool inside(const Vec3& x, const Vec3& lo, const Vec3& hi) {
  for (int a = 0; a < 3; ++a)
    if (x[a] < lo[a] || x[a] > hi[a]) return false;
  return true;
}

// Least-squares line through the bins [first, last) whose height is in [low, high].
FlankFit fit_flank(const SurfaceProfile& p, std::size_t first, std::size_t last, double low, double high) {
  FlankFit fit;
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t k = first; k < last; ++k) {
    const double x = p.position[k], y = p.height[k];
    if (y < low || y > high) continue;
    n += 1, sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  fit.bins = static_cast<int>(n);
  const double det = n * sxx - sx * sx;
  if (n < 3 || det <= 0) {
    fit.angle_deg = std::numeric_limits<double>::quiet_NaN();
    return fit;
  }
  fit.slope = (n * sxy - sx * sy) / det;
  fit.intercept = (sy - fit.slope * sx) / n;
  fit.angle_deg = std::atan(std::abs(fit.slope)) * 180.0 / M_PI;
  return fit;
}

}  // namespace

SurfaceProfile surface_profile(const Snapshot& snapshot, const ProfileSettings& s) {
  if (!(s.bin > 0)) throw std::invalid_argument("repose profile: bin width must be positive");
  const double lo = s.region_lo[s.axis], hi = s.region_hi[s.axis];
  const auto bins = static_cast<std::size_t>(std::max(1.0, std::ceil((hi - lo) / s.bin)));
  SurfaceProfile p;
  p.position.resize(bins);
  p.height.assign(bins, 0.0);
  for (std::size_t k = 0; k < bins; ++k) p.position[k] = lo + (static_cast<double>(k) + 0.5) * s.bin;
  for (const ParticleRecord& q : snapshot.particles) {
    if (q.fixed || !inside(q.position, s.region_lo, s.region_hi)) continue;
    const auto k = std::min(bins - 1, static_cast<std::size_t>((q.position[s.axis] - lo) / s.bin));
    p.height[k] = std::max(p.height[k], q.position.z + q.radius - s.floor);
  }
  return p;
}

ReposeResult measure_repose(const Snapshot& snapshot, const ProfileSettings& s) {
  ReposeResult r;
  r.profile = surface_profile(snapshot, s);
  for (const ParticleRecord& q : snapshot.particles)
    if (!q.fixed && inside(q.position, s.region_lo, s.region_hi)) ++r.particles;
  const auto& h = r.profile.height;
  const auto top = static_cast<std::size_t>(std::max_element(h.begin(), h.end()) - h.begin());
  r.pile_height = h[top];
  r.apex = r.profile.position[top];
  const double low = s.fit_low * r.pile_height, high = s.fit_high * r.pile_height;
  r.left = fit_flank(r.profile, 0, top + 1, low, high);
  r.right = fit_flank(r.profile, top, h.size(), low, high);
  const bool l = std::isfinite(r.left.angle_deg), rr = std::isfinite(r.right.angle_deg);
  r.angle_deg = l && rr ? 0.5 * (r.left.angle_deg + r.right.angle_deg)
                : l    ? r.left.angle_deg
                : rr   ? r.right.angle_deg
                       : std::numeric_limits<double>::quiet_NaN();
  return r;
}

}  // namespace talus::repose
