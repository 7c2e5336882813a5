// A World spread over a grid of ranks (parallel/rank_grid.h).
#include <limits>
#include <stdexcept>

#include "talus/world/world.h"

namespace talus {

double World::particle_skin(double largest_radius) const {
  return settings_.skin > 0 ? settings_.skin : 0.3 * largest_radius;
}

void World::distribute(const Communicator& comm, RankCounts counts, int slab_axis) {
  const ParticleStore& p = particles_;
  const Domain& domain = settings_.domain;
  std::vector<Vec3> position(p.position.begin(), p.position.begin() + p.owned);
  double r_max = 0;
  Vec3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::infinity()};
  Vec3 hi = -1.0 * lo;
  for (std::size_t i = 0; i < p.owned; ++i) {
    position[i] = domain.wrap(position[i]);
    r_max = std::max(r_max, p.radius[i]);
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], position[i][a]), hi[a] = std::max(hi[a], position[i][a]);
  }
  const double range = 2 * r_max + particle_skin(r_max);
  if (slab_axis < 0) {  // the axis one rank would sort its slabs along: the most even one
    CellGrid grid;
    grid.setup(domain, position, position.size(), range);
    slab_axis = grid.slab_axis();
  }
  if (counts == RankCounts{0, 0, 0}) {
    Vec3 extent;
    for (int a = 0; a < 3; ++a) extent[a] = domain.periodic[a] ? domain.length(a) : std::max(0.0, hi[a] - lo[a]);
    counts = RankGrid::choose_counts(comm.size(), extent, {domain.periodic[0], domain.periodic[1], domain.periodic[2]},
                                     range, slab_axis);
  }
  distribute(RankGrid::balanced(comm, domain, counts, position, range, slab_axis));
}

bool World::owns(const Vec3& position) const {
  return !distributed() || spread_.ranks.owns(settings_.domain.wrap(position));
}

void World::distribute(const RankGrid& ranks) {
  ParticleStore& p = particles_;
  const Domain& domain = settings_.domain;
  spread_.ranks = ranks;
  const bool stepping = ready_;
  remove_particles_if([&](std::size_t i) { return !spread_.ranks.owns(domain.wrap(p.position[i])); });
  // A world that has stepped keeps its forces (those of the end of its last step: a fresh force
  // pass would see other velocities in the damping) and only rebuilds its lists, with halos.
  if (stepping) {
    rebuild();
    ready_ = true;
  }
}

}  // namespace talus
