#include "talus/analysis/fabric.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace talus {
namespace {

// Branch vectors of the network, one per contact point or per pair.
std::vector<Vec3> branches(const Snapshot& snapshot, PairPoints points) {
  std::vector<Vec3> out;
  for (const ForceSegment& s : force_network(snapshot, points)) out.push_back(s.to - s.from);
  return out;
}

}  // namespace

FabricHistogram fabric_angle_histogram(const Snapshot& snapshot, int bins, PairPoints points) {
  if (bins < 1) throw std::invalid_argument("fabric_angle_histogram: bins must be positive");
  const double pi = std::numbers::pi, width = pi / bins;
  FabricHistogram h;
  for (int k = 0; k <= bins; ++k) h.edges.push_back(k * width);
  for (int k = 0; k < bins; ++k) h.centres.push_back((k + 0.5) * width);
  std::vector<double> counts(bins, 0.0);
  for (const Vec3& b : branches(snapshot, points)) {
    if (b.x == 0 && b.z == 0) continue;
    double theta = std::atan2(b.z, b.x);
    if (theta < 0) theta += pi;
    const int k = std::clamp(static_cast<int>(theta / width), 0, bins - 1);  // theta = pi folds to the last bin
    counts[k] += 1;
    ++h.samples;
  }
  h.density.resize(bins, 0.0);
  if (h.samples > 0) {
    for (int k = 0; k < bins; ++k) h.density[k] = counts[k] / (static_cast<double>(h.samples) * width);
  }
  return h;
}

FabricTensor fabric_tensor(const Snapshot& snapshot, PairPoints points) {
  FabricTensor phi{};
  int count = 0;
  for (const Vec3& b : branches(snapshot, points)) {
    const Vec3 n = normalized_or_zero(b);
    if (n == Vec3{}) continue;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) phi[r][c] += n[r] * n[c];
    ++count;
  }
  if (count > 0) {
    for (auto& row : phi)
      for (double& v : row) v /= count;
  }
  return phi;
}

PlaneFabric fabric_xz(const Snapshot& snapshot, PairPoints points) {
  PlaneFabric f;
  int count = 0;
  for (const Vec3& b : branches(snapshot, points)) {
    const double len = std::hypot(b.x, b.z);
    if (len == 0) continue;
    const double nx = b.x / len, nz = b.z / len;
    f.xx += nx * nx;
    f.xz += nx * nz;
    f.zz += nz * nz;
    ++count;
  }
  if (count == 0) return f;
  f.xx /= count;
  f.xz /= count;
  f.zz /= count;
  // Symmetric 2x2: eigenvalues (xx + zz)/2 +- r, major axis at half the angle of (xx - zz, 2 xz).
  const double r = std::hypot(0.5 * (f.xx - f.zz), f.xz);
  f.anisotropy = 4.0 * r;
  f.direction = 0.5 * std::atan2(2.0 * f.xz, f.xx - f.zz);
  if (f.direction < 0) f.direction += std::numbers::pi;
  return f;
}

}  // namespace talus
