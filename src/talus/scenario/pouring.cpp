#include "talus/scenario/pouring.h"

#include <numbers>

#include "talus/math/random_orientation.h"
#include "talus/parallel/communicator.h"
#include "talus/scenario/insertion.h"
#include "talus/world/wall_clearance.h"

namespace talus {

std::size_t Pouring::pour_due(World& world) {
  if (done()) return 0;
  if (next_time_ < 0) next_time_ = spec_.start_time;
  if (world.time() < next_time_) return 0;
  next_time_ += spec_.interval;

  // Free places are judged against every particle now in or near the region.
  const Domain& domain = world.settings().domain;
  const double margin = 2 * spec_.radius_max;
  const Vec3 lo = spec_.region_lo - Vec3{margin, margin, margin}, hi = spec_.region_hi + Vec3{margin, margin, margin};
  const bool open[3] = {false, false, false};
  SphereOverlapIndex index(lo, hi, open, 2 * spec_.radius_max);
  const ParticleStore& p = world.particles();
  std::vector<std::byte> near_here;  // the particles near the region, of every rank when distributed
  ByteWriter w(near_here);
  for (std::size_t i = 0; i < p.owned; ++i) {
    const Vec3 x = domain.wrap(p.position[i]);
    bool near = true;
    for (int a = 0; a < 3; ++a) near = near && x[a] >= lo[a] - p.radius[i] && x[a] <= hi[a] + p.radius[i];
    if (near) w.put(PlacedSphere{x, p.radius[i]});
  }
  const std::vector<std::byte> near = world.distributed() ? world.communicator().all_gather(near_here) : near_here;
  for (ByteReader r(near); !r.done();) index.insert(r.get<PlacedSphere>());
  std::uniform_real_distribution<double> unit(0, 1);
  const Vec3 size = spec_.region_hi - spec_.region_lo;
  std::size_t added = 0;
  for (std::size_t attempt = 0; attempt < 20 * spec_.batch && added < spec_.batch && !done(); ++attempt) {
    const double r = spec_.radius_min + (spec_.radius_max - spec_.radius_min) * unit(rng_);
    const Vec3 x{spec_.region_lo.x + size.x * unit(rng_), spec_.region_lo.y + size.y * unit(rng_),
                 spec_.region_lo.z + size.z * unit(rng_)};
    if (index.overlaps({x, r}) || sphere_cuts_a_wall(world.walls(), world.time(), x, r)) continue;
    index.insert({x, r});
    ParticleInit init;
    if (spec_.rigid) {
      init = spec_.prototype;
      init.orientation = random_orientation(rng_);
    } else {
      init.radius = r;
      init.mass = spec_.density * 4.0 / 3.0 * std::numbers::pi * r * r * r;
      const double inertia = 0.4 * init.mass * r * r;
      init.inertia = {inertia, inertia, inertia};
      init.species = spec_.species;
    }
    init.position = x;
    init.velocity = spec_.velocity;
    // Every rank draws the same places (the same generator, the same neighbours); the owner adds each.
    if (world.owns(x))
      world.add_particle(init);
    else
      world.skip_global_id();
    ++added;
    ++poured_;
  }
  return added;
}

}  // namespace talus
