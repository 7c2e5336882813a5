// A World spread over a grid of ranks (parallel/rank_grid.h).
#include <algorithm>
#include <array>
#include <limits>
#include <stdexcept>

#include "talus/world/world.h"

#include "talus/parallel/migration.h"

namespace talus {

double World::particle_skin(double largest_radius) const {
  return settings_.skin > 0 ? settings_.skin : 0.3 * largest_radius;
}

namespace {

// Rank 0's grid on every rank: its cuts, which of them follow the particles, its slab axis.
RankGrid grid_of_first_rank(const RankGrid& mine, const Communicator& comm, const Domain& domain) {
  std::vector<std::byte> bytes;
  if (comm.rank() == 0) {
    ByteWriter w(bytes);
    w.put(mine.slab_axis);
    for (const SlabDecomposition& axis : mine.axes) {
      w.put(axis.min_width);
      w.put(axis.rebalance);
      w.put(static_cast<std::uint64_t>(axis.cut.size()));
      for (const double c : axis.cut) w.put(c);
    }
  }
  const std::vector<std::byte> all = comm.all_gather(bytes);
  ByteReader r(all);
  const int slab_axis = r.get<int>();
  std::array<std::vector<double>, 3> cut;
  std::array<bool, 3> rebalance{};
  std::array<double, 3> min_width{};
  for (int a = 0; a < 3; ++a) {
    min_width[a] = r.get<double>();
    rebalance[a] = r.get<bool>();
    cut[a].resize(r.get<std::uint64_t>());
    for (double& c : cut[a]) c = r.get<double>();
  }
  // Every axis as on rank 0: an uncut axis has no narrowest slab, a cut one the interaction
  // range, which later rebalancing must respect alike on every rank.
  RankGrid grid = RankGrid::with_cuts(comm, domain, std::move(cut), *std::max_element(min_width.begin(), min_width.end()),
                                      slab_axis);
  for (int a = 0; a < 3; ++a) grid.axes[a].min_width = min_width[a], grid.axes[a].rebalance = rebalance[a];
  return grid;
}

}  // namespace

void World::distribute(const Communicator& comm, RankCounts counts, int slab_axis) {
  // A world built on rank 0 alone has the whole system there: rank 0 chooses the grid and
  // sends each rank its particles.
  const bool on_first_rank = settings_.particles_on_first_rank && comm.distributed();
  if (on_first_rank && ready_)
    throw std::logic_error("World::distribute: a world built on rank 0 alone is spread before its first step");
  settings_.particles_on_first_rank = false;  // from now on each rank adds what it owns
  RankGrid grid;
  if (!on_first_rank || comm.rank() == 0) grid = grid_for_whole_system(comm, counts, slab_axis);
  if (!on_first_rank) {
    distribute(grid);
    return;
  }
  spread_.ranks = grid_of_first_rank(grid, comm, settings_.domain);
  spread_.migrated += scatter_from_first_rank(particles_, spread_.ranks, settings_.domain);
  invalidate();
}

RankGrid World::grid_for_whole_system(const Communicator& comm, RankCounts counts, int slab_axis) const {
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
  return RankGrid::balanced(comm, domain, counts, position, range, slab_axis);
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
