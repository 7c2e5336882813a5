#include "talus/world/world.h"

#include <malloc.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "talus/integrate/velocity_verlet.h"
#include "talus/parallel/migration.h"
#include "talus/world/parallel.h"

namespace talus {

namespace {
// Large arrays come straight from the system (mmap) and go back to it when freed. Left alone,
// glibc raises its mmap threshold at the first such free, and the arrays that every neighbour
// rebuild allocates and frees then stay resident in the heap (a third of the peak memory of
// the 32,000-particle chute).
void return_large_arrays_to_system() {
  static const bool done = [] { return mallopt(M_MMAP_THRESHOLD, 256 * 1024) == 1; }();
  (void)done;
}
}  // namespace

World::World(const WorldSettings& settings) : settings_(settings) { return_large_arrays_to_system(); }

std::uint32_t World::add_particle(const ParticleInit& init) {
  if (!(init.radius > 0)) throw std::invalid_argument("particle radius must be positive");
  if (!(init.mass > 0)) throw std::invalid_argument("particle mass must be positive");
  particles_.drop_ghosts();
  const std::size_t n = particles_.owned;
  particles_.resize(n + 1);
  particles_.owned = n + 1;
  particles_.position[n] = init.position;
  particles_.velocity[n] = init.fixed ? Vec3{} : init.velocity;
  particles_.angular_velocity[n] = init.fixed ? Vec3{} : init.angular_velocity;
  particles_.force[n] = {};
  particles_.torque[n] = {};
  particles_.orientation[n] = init.orientation;
  particles_.radius[n] = init.radius;
  particles_.mass[n] = init.mass;
  particles_.inv_mass[n] = init.fixed ? 0.0 : 1.0 / init.mass;
  particles_.inv_inertia[n] = init.fixed ? Vec3{} : Vec3{1 / init.inertia.x, 1 / init.inertia.y, 1 / init.inertia.z};
  particles_.species[n] = init.species;
  particles_.shape[n] = init.shape;
  particles_.gid[n] = next_gid_;
  invalidate();
  return next_gid_++;
}

std::uint32_t World::add_sphere(const Vec3& position, double radius, double density, int species, bool fixed) {
  ParticleInit init;
  init.position = position;
  init.radius = radius;
  init.mass = density * 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  const double i = 0.4 * init.mass * radius * radius;
  init.inertia = {i, i, i};
  init.species = species;
  init.fixed = fixed;
  return add_particle(init);
}

int World::add_shape(const CompositeShape& shape) {
  shapes_.push_back(shape);
  invalidate();
  return static_cast<int>(shapes_.size()) - 1;
}

bool World::has_composites() const { return shapes_.size() > 1; }

// A rigid body's rotation (free_rotation, sines and cosines) costs about 16 sphere updates.
std::size_t World::integration_cost() const { return has_composites() ? 16 : 1; }

int World::add_wall(const Wall& wall) {
  walls_.push_back(wall);
  invalidate();
  return static_cast<int>(walls_.size()) - 1;
}

double World::interaction_range() const {
  double r_max = 0;
  for (std::size_t i = 0; i < particles_.owned; ++i) r_max = std::max(r_max, particles_.radius[i]);
  return 2 * communicator().max(r_max) + skin_;
}

const Communicator& World::communicator() const {
  return distributed() ? *slabs_.comm : Communicator::alone();
}

MemoryLayout World::memory_layout() const {
  MemoryLayout m;
  const bool rolling = table_.any_rolling();
  m.spring = settings_.tangential_model != TangentialModel::memoryless;
  m.normal_prev = settings_.tangential_model != TangentialModel::elastic_spring || rolling;
  m.rolling = rolling && settings_.tangential_model != TangentialModel::memoryless;
  return m;
}

void World::prepare() {
  if (table_.species() == 0) throw std::logic_error("contact parameters are not set");
  double r_max = 0;
  for (std::size_t i = 0; i < particles_.owned; ++i) {
    r_max = std::max(r_max, particles_.radius[i]);
    if (particles_.species[i] < 0 || particles_.species[i] >= table_.species())
      throw std::logic_error("particle species without contact parameters");
  }
  skin_ = particle_skin(communicator().max(r_max));
  wall_force_.assign(walls_.size(), Vec3{});
  rebuild();
  std::fill(particles_.force.begin(), particles_.force.end(), Vec3{});
  std::fill(particles_.torque.begin(), particles_.torque.end(), Vec3{});
  compute_forces(0.0);  // forces at t0; memories do not advance
  ready_ = true;
}

bool World::needs_rebuild() const {
  if (2 * max_displacement_ > skin_) return true;
  double wall_move = 0;
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    if (static_cast<char>(walls_[w].active(time_)) != wall_active_at_build_[w]) return true;
    if (!walls_[w].moves()) continue;  // Wall::moves: only the normal motion counts
    const Vec3 moved = walls_[w].origin_at(time_) - wall_origin_at_build_[w];
    wall_move = std::max(wall_move, std::abs(dot(moved, walls_[w].normal)));
  }
  return max_displacement_ + wall_move > skin_;
}

void World::rebuild() {
  ScopedPhase phase(timer_, Phase::neighbors);
  ParticleStore& p = particles_;
  p.drop_ghosts();
  const Domain& domain = settings_.domain;
  {
    const long owned = static_cast<long>(p.owned);
#pragma omp parallel for schedule(static) if (worth_parallel(p.owned))
    for (long i = 0; i < owned; ++i) p.position[i] = domain.wrap(p.position[i]);
  }

  const double range = interaction_range();
  // Along the axis of a distributed world's slabs, the halo is the periodic image.
  Domain image_domain = domain;
  if (distributed()) image_domain.periodic[slabs_.axis] = false;
  for (int a = 0; a < 3; ++a)
    if (image_domain.periodic[a] && domain.length(a) < 2 * range)
      throw std::runtime_error("periodic box narrower than twice the interaction range");

  // The memories the new list must find, compact (the entries in contact only), so that the
  // new list is built in the old one's memory: the two never coexist at the peak.
  CarriedContacts& carried = carried_;
  pairs_.carry(gid_at_build_, next_gid_, has_composites(), carried);
  pairs_.clear();
  // A distributed world carries its wall memories by global id too, as particles change rank,
  // and shaped bodies their contact points with them, as plain lists.
  std::vector<WallMemoryRecord> wall_memories;
  const bool points_travel = distributed() && has_composites();
  std::vector<SubContactList> wall_points;
  if (distributed()) {
    ScopedPhase exchange(timer_, Phase::exchange);
    std::vector<std::uint32_t> wall_entries;
    wall_memories = wall_pairs_.carry(gid_at_build_, points_travel, points_travel ? &wall_entries : nullptr);
    if (points_travel) {
      carried.points.resize(carried.entry.size());
      for (std::size_t k = 0; k < carried.entry.size(); ++k) carried.points[k] = pair_sub_.list_of(carried.entry[k]);
      wall_points.resize(wall_entries.size());
      for (std::size_t k = 0; k < wall_entries.size(); ++k) wall_points[k] = wall_sub_.list_of(wall_entries[k]);
    }
    std::vector<double> coordinate(p.owned);
    for (std::size_t i = 0; i < p.owned; ++i) coordinate[i] = p.position[i][slabs_.axis];
    slabs_.rebalance_by_count(coordinate);
    migrated_ += migrate(p, slabs_, carried, wall_memories, memory_layout(), next_gid_,
                         points_travel ? &wall_points : nullptr).left;
  }
  const long owned = static_cast<long>(p.owned);
  grid_.setup(distributed() ? slab_grid_domain() : domain, p.position, p.owned, range,
              distributed() ? slabs_.axis : -1);

  // Sort owned particles by cell, slab axis slowest: slabs become contiguous and neighbours
  // close in memory. A stable counting sort; the cells are recomputed after the sort rather
  // than permuted, which needs no second array.
  // Kept between rebuilds, as are the carried memories: mapping their pages afresh each time
  // cost more than a tenth of a rebuild (see make_room in pair_list.cpp), and both are alive
  // at the rebuild's peak anyway.
  std::vector<CellCoord>& cell_of = cell_of_;
  if (p.owned + ghosts_.count() > cell_of.capacity()) {  // ghosts append theirs: room for an eighth more
    std::vector<CellCoord>().swap(cell_of);
    cell_of.reserve(p.owned + ghosts_.count() + ghosts_.count() / 8 + 64);
  }
  cell_of.resize(p.owned);
  {
    // Each thread counts its block of particles per cell; the ranks run cell by cell and, within
    // a cell, block by block, so the sort is stable and the same on any team.
    const int threads = worth_parallel(p.owned) ? omp_get_max_threads() : 1;
    const std::size_t cells = static_cast<std::size_t>(grid_.linear_size());
    std::vector<std::uint32_t> cell(p.owned), from(p.owned);  // from: the permutation's source of each place
    std::vector<std::vector<std::uint32_t>> next(threads);  // per block and cell: count, then next rank
#pragma omp parallel num_threads(threads)
    {
      const int t = omp_get_thread_num(), team = omp_get_num_threads();
      const long lo = owned * t / team, hi = owned * (t + 1) / team;
      std::vector<std::uint32_t>& mine = next[t];
      mine.assign(cells, 0);
      for (long i = lo; i < hi; ++i) {
        cell_of[i] = grid_.coord_of(p.position[i]);
        cell[i] = static_cast<std::uint32_t>(grid_.linear(cell_of[i]));
        ++mine[cell[i]];
      }
#pragma omp barrier
#pragma omp single
      {
        std::uint32_t rank = 0;
        for (std::size_t c = 0; c < cells; ++c)
          for (int b = 0; b < team; ++b) {
            const std::uint32_t n = next[b][c];
            next[b][c] = rank;
            rank += n;
          }
      }
      for (long i = lo; i < hi; ++i) from[mine[cell[i]]++] = static_cast<std::uint32_t>(i);
    }
    std::vector<std::uint32_t>().swap(cell);  // the counts go before the permutation's scratch comes
    std::vector<std::vector<std::uint32_t>>().swap(next);
    p.permute_owned(from);
  }
#pragma omp parallel for schedule(static) if (worth_parallel(p.owned))
  for (long i = 0; i < owned; ++i) cell_of[i] = grid_.coord_of(p.position[i]);
  ghosts_.create(p, image_domain, grid_, range, cell_of);
  if (distributed()) {
    ScopedPhase exchange(timer_, Phase::exchange);
    halo_.create(p, slabs_, grid_, range, cell_of);
  }
  grid_.bin(cell_of);

  const MemoryLayout layout = memory_layout();
  pairs_.build(p, cell_of, grid_, skin_, layout);
  budgets_.clear();  // new entries, and the travels restart
  placed_.restart_travel();
  std::vector<std::int64_t> origin;
  pairs_.restore_memory(carried, p.gid, has_composites() ? &origin : nullptr);
  if (has_composites())
    pair_sub_ = points_travel ? SubContactStore::from_lists(pairs_, origin, carried.points)
                              : pair_sub_.carried_to(pairs_, origin);

  WallContactList old_walls = std::move(wall_pairs_);
  wall_pairs_ = WallContactList{};
  wall_pairs_.build(p, walls_, time_, skin_, layout);
  if (distributed())
    wall_pairs_.restore_memory(wall_memories, p.gid, next_gid_, has_composites() ? &origin : nullptr);
  else
    wall_pairs_.transfer_memory(old_walls, gid_at_build_, p.gid, next_gid_, has_composites() ? &origin : nullptr);
  if (has_composites())
    wall_sub_ = points_travel ? SubContactStore::from_lists(wall_pairs_, origin, wall_points)
                              : wall_sub_.carried_to(wall_pairs_, origin);
  gid_at_build_ = p.gid;  // owned and ghost ids of this build, for the next transfer
  mark_step_ends();

  position_at_build_.assign(p.position.begin(), p.position.begin() + p.owned);
  wall_origin_at_build_.resize(walls_.size());
  wall_active_at_build_.resize(walls_.size());
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    wall_origin_at_build_[w] = walls_[w].origin_at(time_);
    wall_active_at_build_[w] = walls_[w].active(time_);
  }
  time_at_build_ = time_;
  max_displacement_ = 0;
  ++rebuilds_;
}

void World::mark_step_ends() {
  const ParticleStore& p = particles_;
  const std::size_t owned = p.owned;
  step_end_.resize(owned);
  late_.clear();
  inline_owner_.clear();
  late_owner_.clear();
  inline_owner_start_.assign(pairs_.slabs() + 1, 0);
  if (has_composites()) return;  // rigid bodies end their steps in a pass of their own
  // In parallel: the rebuild's serial parts keep the second thread waiting.
  const long n = static_cast<long>(owned);
  const long wall_rows = static_cast<long>(std::min(owned, wall_pairs_.rows()));
  const long owners = static_cast<long>(ghosts_.owners());
  const bool parallel = worth_parallel(owned);
#pragma omp parallel if (parallel)
  {
#pragma omp for schedule(static)
    for (long i = 0; i < n; ++i) {
      const bool late = i < wall_rows && wall_pairs_.row_begin(i) != wall_pairs_.row_end(i);
      step_end_[i] = late                       ? StepEndKind::late
                     : is_plain_sphere(p, i) ? StepEndKind::plain_sphere
                                             : StepEndKind::other;
    }
#pragma omp for schedule(static)
    for (long k = 0; k < owners; ++k) step_end_[ghosts_.owner_at(k)] = StepEndKind::late;
  }
  // Particles with copies on the rank below wait for their forces from there.
  for (const std::uint32_t k : halo_.sent_indices())
    step_end_[k < owned ? k : ghosts_.owner(k - owned)] = StepEndKind::late;
  for (std::size_t i = 0; i < owned; ++i)
    if (step_end_[i] == StepEndKind::late) late_.push_back(static_cast<std::uint32_t>(i));

  // A slab ends once its rows and the previous slab's are done (World::pair_forces). Those rows
  // are all that touch a ghost in that slab: rows list their own slab and the next one up. So
  // an owner whose ghosts all share its slab can end with it, while its data is in cache; only
  // the images across the slab axis's faces wait for the whole pass. (With walls, every late
  // particle waits for the ghost fold and the wall forces instead: the lists stay empty.)
  if (!walls_.empty() || distributed()) return;
  std::size_t slab = 0;
  for (std::size_t k = 0; k < ghosts_.owners(); ++k) {
    if (!ghosts_.ghosts_share_layer(k, grid_.slab_axis())) {
      late_owner_.push_back(static_cast<std::uint32_t>(k));
      continue;
    }
    while (ghosts_.owner_at(k) >= pairs_.slab_end(slab)) ++slab;  // owners ascend, as do slabs
    ++inline_owner_start_[slab + 1];
    inline_owner_.push_back(static_cast<std::uint32_t>(k));
  }
  for (std::size_t s = 0; s + 1 < inline_owner_start_.size(); ++s) inline_owner_start_[s + 1] += inline_owner_start_[s];
  // Images across the slab axis are made on its high side only, of particles within one
  // range of its low face: in the first slab, as cells are at least one range wide.
  late_owners_in_first_slab_ = true;
  for (const std::uint32_t k : late_owner_)
    late_owners_in_first_slab_ &= pairs_.slabs() > 0 && ghosts_.owner_at(k) < pairs_.slab_end(0);
}

void World::run(std::uint64_t steps) {
  if (steps == 0) return;
  if (!ready_) prepare();
  const double dt = settings_.time_step;
  if (has_composites() || !settings_.fused_step_end) {
    // The first step opens with its own half kick; each later one also closes the step before.
    for (std::uint64_t k = 0; k < steps; ++k) {
      open_step(k == 0 ? 1 : 2);
      compute_forces(dt);
      ++steps_;
    }
    ScopedPhase phase(timer_, Phase::integrate);
    kick(particles_, 0.5 * dt, settings_.gravity, integration_cost());
    return;
  }
  // Spheres: each particle's step ends (closing kick, and the next step's opening kick and
  // drift) within the force pass, as soon as its force is complete.
  open_step(1);
  for (std::uint64_t k = 0; k < steps; ++k) {
    StepEnd end;
    end.next_step = k + 1 < steps;
    end.h = 0.5 * dt;
    end.dt = dt;
    end.gravity = settings_.gravity;
    end.position_at_build = position_at_build_.data();
    const double max_d2 = compute_forces_ending_step(dt, end);
    ++steps_;
    if (end.next_step) {
      max_displacement_ = std::sqrt(max_d2);
      move_to_next_step();
    }
  }
}

void World::open_step(int opening_kicks) {
  const double dt = settings_.time_step;
  {
    ScopedPhase phase(timer_, Phase::integrate);
    // Also zeroes the owned forces: the kicks were their last readers.
    max_displacement_ = std::sqrt(kick_drift(particles_, opening_kicks, 0.5 * dt, dt, settings_.gravity,
                                             position_at_build_, integration_cost()));
  }
  move_to_next_step();
}

void World::move_to_next_step() {
  time_ += settings_.time_step;
  if (communicator().any(needs_rebuild())) {
    rebuild();  // new ghosts copy the current state, with zero forces
  } else {
    if (!ghosts_fresh_) ghosts_.refresh(particles_);
    if (distributed()) {  // after the periodic images, which the rank below may hold copies of
      ScopedPhase exchange(timer_, Phase::exchange);
      halo_.forward(particles_);
    }
  }
  ghosts_fresh_ = false;
}

Domain World::slab_grid_domain() const {
  // The slab, as if periodic: the grid tiles it and keeps a layer above for the halo. An end
  // of a non-periodic axis is where the outermost particle is.
  Domain d = settings_.domain;
  const int a = slabs_.axis;
  const ParticleStore& p = particles_;
  double lo = slabs_.lo(), hi = slabs_.hi();
  if (!std::isfinite(lo) || !std::isfinite(hi)) {
    double mn = std::numeric_limits<double>::infinity(), mx = -mn;
    for (std::size_t i = 0; i < p.owned; ++i) mn = std::min(mn, p.position[i][a]), mx = std::max(mx, p.position[i][a]);
    if (!std::isfinite(lo)) lo = std::isfinite(mn) ? mn : (std::isfinite(hi) ? hi - 1 : 0.0);
    if (!std::isfinite(hi)) hi = std::isfinite(mx) ? std::max(mx, lo) : lo + 1;
    if (!(hi > lo)) hi = lo + 1e-9 * std::max(1.0, std::abs(lo));
  }
  d.lo[a] = lo;
  d.hi[a] = hi;
  d.periodic[a] = true;
  return d;
}

std::vector<std::int32_t> World::index_of_gid() const {
  std::vector<std::int32_t> index(next_gid_, -1);
  for (std::size_t i = 0; i < particles_.owned; ++i) index[particles_.gid[i]] = static_cast<std::int32_t>(i);
  return index;
}

std::size_t World::memory_bytes() const {
  const ParticleStore& p = particles_;
  const std::size_t per_particle = 6 * sizeof(Vec3) + sizeof(Quat) + 3 * sizeof(double) + 3 * 4;
  return p.position.capacity() * per_particle + pairs_.bytes() + carried_.bytes() +
         cell_of_.capacity() * sizeof(CellCoord) + position_at_build_.capacity() * sizeof(Vec3) +
         step_end_.capacity() +
         (late_.capacity() + inline_owner_.capacity() + inline_owner_start_.capacity() + late_owner_.capacity()) *
             sizeof(std::uint32_t);
}

}  // namespace talus
