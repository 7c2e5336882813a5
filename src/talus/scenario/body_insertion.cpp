#include "talus/scenario/body_insertion.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "talus/collide/convex_contact.h"
#include "talus/math/random_orientation.h"

namespace talus {

namespace {

// The parts of a body in the world; a sphere is one part.
std::vector<std::pair<ConvexShape, Pose>> world_parts(const PlacedBody& b) {
  std::vector<std::pair<ConvexShape, Pose>> parts;
  const Pose body{b.position, b.orientation};
  if (!b.shape) {
    parts.emplace_back(make_sphere(b.radius), body);
    return parts;
  }
  for (const CompositePart& p : b.shape->parts) parts.emplace_back(p.shape, body * p.pose);
  return parts;
}

}  // namespace

bool bodies_overlap(const PlacedBody& a, const PlacedBody& b, double clearance) {
  const double reach = a.radius + b.radius + clearance;
  if (norm2(a.position - b.position) >= reach * reach) return false;
  if (!a.shape && !b.shape) return true;
  for (const auto& [sa, pa] : world_parts(a))
    for (const auto& [sb, pb] : world_parts(b))
      // Sharp boxes go through separating axes, which answer at the first separating one;
      // their rounded contact shapes lie inside the sharp ones, so no overlap is missed.
      if (parts_within(sa, pa, sb, pb, clearance, NarrowPhaseOptions{true})) return true;
  return false;
}

Aabb body_aabb(const PlacedBody& body) {
  Aabb box{body.position, body.position};
  bool first = true;
  for (const auto& [s, pose] : world_parts(body)) {
    const Aabb b = aabb(s, pose);
    for (int a = 0; a < 3; ++a) {
      box.lo[a] = first ? b.lo[a] : std::min(box.lo[a], b.lo[a]);
      box.hi[a] = first ? b.hi[a] : std::max(box.hi[a], b.hi[a]);
    }
    first = false;
  }
  return box;
}

BodyOverlapIndex::BodyOverlapIndex(double max_radius) : cell_(2.1 * max_radius) {  // room for a clearance of 0.1 radius
  if (!(max_radius > 0)) throw std::invalid_argument("BodyOverlapIndex: radius must be positive");
}

std::int64_t BodyOverlapIndex::key(const Vec3& x) const {
  // Bounded before the cast (the hash keeps 21 bits anyway): a far position would not fit.
  const auto c = [&](double v) { return static_cast<std::int64_t>(std::clamp(std::floor(v / cell_), -0x1p62, 0x1p62)) & 0x1fffff; };
  return (c(x.x) << 42) | (c(x.y) << 21) | c(x.z);
}

bool BodyOverlapIndex::overlaps(const PlacedBody& body, double clearance) const {
  if (2 * body.radius + clearance > cell_) throw std::invalid_argument("BodyOverlapIndex: body larger than a cell");
  for (int dx = -1; dx <= 1; ++dx)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dz = -1; dz <= 1; ++dz) {
        const auto it = cells_.find(key(body.position + Vec3{dx * cell_, dy * cell_, dz * cell_}));
        if (it == cells_.end()) continue;
        for (std::uint32_t k : it->second)
          if (bodies_overlap(body, bodies_[k], clearance)) return true;
      }
  return false;
}

void BodyOverlapIndex::insert(const PlacedBody& body) {
  cells_[key(body.position)].push_back(static_cast<std::uint32_t>(bodies_.size()));
  bodies_.push_back(body);
}

std::vector<PlacedBody> insert_bodies_growing(BodyOverlapIndex& index, const PlacedBody& prototype, std::size_t count,
                                              const Vec3& lo, const Vec3& size, double growth, double clearance,
                                              std::mt19937_64& rng, double max_top, std::size_t max_attempts) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<PlacedBody> placed;
  double top = size.z;
  std::size_t misfits = 0, rejections = 0;
  while (placed.size() < count) {
    PlacedBody b = prototype;
    b.orientation = prototype.shape ? random_orientation(rng) : Quat{};
    b.position = {lo.x + size.x * unit(rng), lo.y + size.y * unit(rng), lo.z + top * unit(rng)};
    const Aabb box = body_aabb(b);
    const bool fits = box.lo.x >= lo.x && box.hi.x <= lo.x + size.x && box.lo.y >= lo.y &&
                      box.hi.y <= lo.y + size.y && box.lo.z >= lo.z && box.hi.z <= lo.z + top;
    if (!fits) {
      // Orientations too wide for a narrow region are redrawn; only overlaps grow the region.
      if (++misfits > 1000000) throw std::runtime_error("insertion region too small for the body's shape");
      continue;
    }
    if (index.overlaps(b, clearance)) {
      top += growth;
      // Counted in a row whatever the growth: one too small to move the top never reaches max_top.
      if (top > max_top || ++rejections > max_attempts)
        throw std::runtime_error("insertion region full after " + std::to_string(placed.size()) + " of " +
                                 std::to_string(count) + " particles");
      continue;
    }
    rejections = 0;
    index.insert(b);
    placed.push_back(b);
  }
  return placed;
}

}  // namespace talus
