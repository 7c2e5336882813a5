// A World spread over ranks as slabs (parallel/slab_decomposition.h).
#include <stdexcept>

#include "talus/world/world.h"

namespace talus {

double World::particle_skin(double largest_radius) const {
  return settings_.skin > 0 ? settings_.skin : 0.3 * largest_radius;
}

void World::distribute(const Communicator& comm, int axis) {
  const ParticleStore& p = particles_;
  const Domain& domain = settings_.domain;
  std::vector<Vec3> position(p.position.begin(), p.position.begin() + p.owned);
  double r_max = 0;
  for (std::size_t i = 0; i < p.owned; ++i) {
    position[i] = domain.wrap(position[i]);
    r_max = std::max(r_max, p.radius[i]);
  }
  const double range = 2 * r_max + particle_skin(r_max);
  if (axis < 0) {  // the axis one rank would sort its slabs along: the most even one
    CellGrid grid;
    grid.setup(domain, position, position.size(), range);
    axis = grid.slab_axis();
  }
  std::vector<double> coordinate(position.size());
  for (std::size_t i = 0; i < position.size(); ++i) coordinate[i] = position[i][axis];
  distribute(SlabDecomposition::balanced(comm, domain, axis, std::move(coordinate), range));
}

bool World::owns(const Vec3& position) const {
  return !distributed() || spread_.slabs.owner_of(settings_.domain.wrap(position)[spread_.slabs.axis]) == spread_.slabs.rank();
}

void World::distribute(const SlabDecomposition& slabs) {
  ParticleStore& p = particles_;
  const Domain& domain = settings_.domain;
  spread_.slabs = slabs;
  const bool stepping = ready_;
  const int rank = slabs.rank(), axis = slabs.axis;
  remove_particles_if([&](std::size_t i) { return spread_.slabs.owner_of(domain.wrap(p.position[i])[axis]) != rank; });
  // A world that has stepped keeps its forces (those of the end of its last step: a fresh force
  // pass would see other velocities in the damping) and only rebuilds its lists, with halos.
  if (stepping) {
    rebuild();
    ready_ = true;
  }
}

}  // namespace talus
