#include "talus/scenario/body_insertion.h"

#include <array>
#include <cmath>
#include <unordered_map>
#include <variant>

#include "talus/collide/box_box.h"
#include "talus/collide/convex_contact.h"

namespace talus {

bool bodies_overlap(const CompositeShape& shape, const PlacedBody& a, const PlacedBody& b, double clearance) {
  const Pose body_a{a.position, a.orientation}, body_b{b.position, b.orientation};
  const Vec3 grow{0.5 * clearance, 0.5 * clearance, 0.5 * clearance};
  for (const CompositePart& pa : shape.parts) {
    const Pose posed_a = body_a * pa.pose;
    for (const CompositePart& pb : shape.parts) {
      const Pose posed_b = body_b * pb.pose;
      const Vec3 ua = posed_a.orientation.rotate(pa.capsule.half_axis), ub = posed_b.orientation.rotate(pb.capsule.half_axis);
      if (capsules_apart(posed_a.position, ua, pa.capsule.radius + 0.5 * clearance, posed_b.position, ub,
                         pb.capsule.radius + 0.5 * clearance))
        continue;
      const Box* ba = std::get_if<Box>(&pa.shape.geometry);
      const Box* bb = std::get_if<Box>(&pb.shape.geometry);
      if (ba && bb) {
        if (!box_box_sat(ba->half_extents + grow, posed_a, bb->half_extents + grow, posed_b).separated) return true;
        continue;
      }
      const PartContact c = narrow_phase(pa.shape, posed_a, pb.shape, posed_b);
      if (c.delta_n > -clearance) return true;
    }
  }
  return false;
}

namespace {

// Uniform random rotation (Shoemake 1992: a normalised 4D Gaussian).
Quat random_orientation(std::mt19937_64& rng) {
  std::normal_distribution<double> g(0, 1);
  return Quat{g(rng), g(rng), g(rng), g(rng)}.normalized();
}

bool inside(const CompositeShape& shape, const PlacedBody& body, const Vec3& lo, const Vec3& hi) {
  const Pose pose{body.position, body.orientation};
  for (const CompositePart& part : shape.parts) {
    const Aabb box = aabb(part.shape.geometry, pose * part.pose);
    for (int k = 0; k < 3; ++k)
      if (box.lo[k] < lo[k] || (k < 2 && box.hi[k] > hi[k])) return false;
  }
  return true;
}

}  // namespace

std::vector<PlacedBody> insert_bodies(const CompositeShape& shape, std::size_t count, const Vec3& lo, const Vec3& hi,
                                      double growth, std::mt19937_64& rng, double clearance) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double cell = 2 * shape.bounding_radius + clearance;  // bodies farther apart cannot touch
  auto cell_of = [&](const Vec3& x) {
    const long i = static_cast<long>(std::floor((x.x - lo.x) / cell));
    const long j = static_cast<long>(std::floor((x.y - lo.y) / cell));
    const long k = static_cast<long>(std::floor((x.z - lo.z) / cell));
    return std::array<long, 3>{i, j, k};
  };
  auto key = [](long i, long j, long k) { return (i * 4096 + j) * 1048576 + k; };
  std::unordered_map<long, std::vector<std::uint32_t>> cells;
  std::vector<PlacedBody> placed;
  placed.reserve(count);
  double top = hi.z;
  while (placed.size() < count) {
    const PlacedBody b{{lo.x + (hi.x - lo.x) * unit(rng), lo.y + (hi.y - lo.y) * unit(rng), lo.z + (top - lo.z) * unit(rng)},
                       random_orientation(rng)};
    bool ok = inside(shape, b, lo, hi);
    const auto c = cell_of(b.position);
    for (long di = -1; di <= 1 && ok; ++di)
      for (long dj = -1; dj <= 1 && ok; ++dj)
        for (long dk = -1; dk <= 1 && ok; ++dk) {
          const auto it = cells.find(key(c[0] + di, c[1] + dj, c[2] + dk));
          if (it == cells.end()) continue;
          for (std::uint32_t other : it->second)
            if (norm2(placed[other].position - b.position) < cell * cell && bodies_overlap(shape, b, placed[other], clearance)) {
              ok = false;
              break;
            }
        }
    if (!ok) {
      top += growth;
      continue;
    }
    cells[key(c[0], c[1], c[2])].push_back(static_cast<std::uint32_t>(placed.size()));
    placed.push_back(b);
  }
  return placed;
}

}  // namespace talus
