// The neighbours stage of a World's step: when to rebuild, and the rebuild itself (carry the
// contact memories by global id, hand particles to other ranks, sort by cell, make the periodic
// images and the halo, build the pair and wall lists), then how each particle will end its step.
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "talus/parallel/migration.h"
#include "talus/world/parallel.h"
#include "talus/world/world.h"

namespace talus {

bool World::needs_rebuild() const {
  if (2 * lists_.max_displacement > lists_.skin) return true;
  double wall_move = 0;
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    if (static_cast<char>(walls_[w].active(time_)) != lists_.wall_active_at_build[w]) return true;
    if (!walls_[w].moves()) continue;  // Wall::moves: only the normal motion counts
    const Vec3 moved = walls_[w].origin_at(time_) - lists_.wall_origin_at_build[w];
    wall_move = std::max(wall_move, std::abs(dot(moved, walls_[w].normal)));
  }
  return lists_.max_displacement + wall_move > lists_.skin;
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
  // Along the cut axes of a distributed world, the halo makes the periodic images.
  Domain image_domain = domain;
  for (const int a : spread_.ranks.stage_axes()) image_domain.periodic[a] = false;
  for (int a = 0; a < 3; ++a)
    if (image_domain.periodic[a] && domain.length(a) < 2 * range)
      throw std::runtime_error("periodic box narrower than twice the interaction range");

  // The memories the new list must find, compact (the entries in contact only), so that the
  // new list is built in the old one's memory: the two never coexist at the peak.
  std::vector<double> weight;  // of each owned particle, for cuts that balance the contacts' work
  if (distributed() && spread_.ranks.balance == RankGrid::Balance::neighbours) {
    weight.assign(p.owned, 1.0);
    for (std::size_t i = 0; i < std::min(p.owned, lists_.pairs.rows()); ++i)
      weight[i] += lists_.pairs.row_end(i) - lists_.pairs.row_begin(i);
    for (std::size_t i = 0; i < std::min(p.owned, lists_.walls.rows()); ++i)
      weight[i] += lists_.walls.row_end(i) - lists_.walls.row_begin(i);
  }
  CarriedContacts& carried = lists_.carried;
  lists_.pairs.carry(lists_.gid_at_build, has_composites(), carried);
  lists_.pairs.clear();
  // A distributed world carries its wall memories by global id too, as particles change rank,
  // and shaped bodies their contact points with them, as plain lists.
  std::vector<WallMemoryRecord> wall_memories;
  const bool points_travel = distributed() && has_composites();
  std::vector<SubContactList> wall_points;
  if (distributed()) {
    ScopedPhase migration(timer_, Phase::migration);
    std::vector<std::uint32_t> wall_entries;
    wall_memories = lists_.walls.carry(lists_.gid_at_build, points_travel, points_travel ? &wall_entries : nullptr);
    if (points_travel) {
      carried.points.resize(carried.entry.size());
      for (std::size_t k = 0; k < carried.entry.size(); ++k) carried.points[k] = shaped_.pair_points.list_of(carried.entry[k]);
      wall_points.resize(wall_entries.size());
      for (std::size_t k = 0; k < wall_entries.size(); ++k) wall_points[k] = shaped_.wall_points.list_of(wall_entries[k]);
    }
    spread_.ranks.rebalance(std::span<const Vec3>(p.position.data(), p.owned), weight);
    spread_.migrated += migrate(p, spread_.ranks, carried, wall_memories, memory_layout(), spread_.migration,
                                points_travel ? &wall_points : nullptr).left;
  }
  const long owned = static_cast<long>(p.owned);
  lists_.grid.setup(distributed() ? sub_domain_grid() : domain, p.position, p.owned, range,
                    distributed() ? spread_.ranks.slab_axis : -1);

  // Sort owned particles by cell, slab axis slowest: slabs become contiguous and neighbours
  // close in memory. A stable counting sort; the cells are recomputed after the sort rather
  // than permuted, which needs no second array.
  // Kept between rebuilds, as are the carried memories: mapping their pages afresh each time
  // cost more than a tenth of a rebuild (see make_room in pair_list.cpp), and both are alive
  // at the rebuild's peak anyway.
  std::vector<CellCoord>& cell_of = lists_.cell_of;
  if (p.owned + lists_.ghosts.count() > cell_of.capacity()) {  // ghosts append theirs: room for an eighth more
    std::vector<CellCoord>().swap(cell_of);
    cell_of.reserve(p.owned + lists_.ghosts.count() + lists_.ghosts.count() / 8 + 64);
  }
  cell_of.resize(p.owned);
  {
    // Each thread counts its block of particles per cell; the ranks run cell by cell and, within
    // a cell, block by block, so the sort is stable and the same on any team.
    const int threads = worth_parallel(p.owned) ? omp_get_max_threads() : 1;
    const std::size_t cells = static_cast<std::size_t>(lists_.grid.linear_size());
    std::vector<std::uint32_t> cell(p.owned), from(p.owned);  // from: the permutation's source of each place
    std::vector<std::vector<std::uint32_t>> next(threads);  // per block and cell: count, then next rank
#pragma omp parallel num_threads(threads)
    {
      const int t = omp_get_thread_num(), team = omp_get_num_threads();
      const long lo = owned * t / team, hi = owned * (t + 1) / team;
      std::vector<std::uint32_t>& mine = next[t];
      mine.assign(cells, 0);
      for (long i = lo; i < hi; ++i) {
        cell_of[i] = lists_.grid.coord_of(p.position[i]);
        cell[i] = static_cast<std::uint32_t>(lists_.grid.linear(cell_of[i]));
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
  for (long i = 0; i < owned; ++i) cell_of[i] = lists_.grid.coord_of(p.position[i]);
  lists_.ghosts.create(p, image_domain, lists_.grid, range, cell_of);
  if (distributed()) {
    ScopedPhase migration(timer_, Phase::migration);
    spread_.halo.create(p, spread_.ranks, lists_.grid, range, cell_of, has_composites());
  }
  lists_.grid.bin(cell_of);

  const MemoryLayout layout = memory_layout();
  lists_.pairs.build(p, cell_of, lists_.grid, lists_.skin, layout);
  shaped_.budgets.clear();  // new entries, and the travels restart
  shaped_.block_wake.clear();  // its bounds are on the old travels' scale, its entries the old list's
  shaped_.placed.restart_travel();
  std::vector<std::int64_t> origin;
  lists_.pairs.restore_memory(carried, p.gid, has_composites() ? &origin : nullptr);
  if (has_composites())
    shaped_.pair_points = points_travel ? SubContactStore::from_lists(lists_.pairs, origin, carried.points)
                              : shaped_.pair_points.carried_to(lists_.pairs, origin);

  WallContactList old_walls = std::move(lists_.walls);
  lists_.walls = WallContactList{};
  lists_.walls.build(p, walls_, time_, lists_.skin, layout);
  if (distributed())
    lists_.walls.restore_memory(wall_memories, p.gid, has_composites() ? &origin : nullptr);
  else
    lists_.walls.transfer_memory(old_walls, lists_.gid_at_build, p.gid, has_composites() ? &origin : nullptr);
  if (has_composites())
    shaped_.wall_points = points_travel ? SubContactStore::from_lists(lists_.walls, origin, wall_points)
                              : shaped_.wall_points.carried_to(lists_.walls, origin);
  lists_.gid_at_build = p.gid;  // owned and ghost ids of this build, for the next transfer
  mark_step_ends();

  lists_.position_at_build.assign(p.position.begin(), p.position.begin() + p.owned);
  lists_.wall_origin_at_build.resize(walls_.size());
  lists_.wall_active_at_build.resize(walls_.size());
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    lists_.wall_origin_at_build[w] = walls_[w].origin_at(time_);
    lists_.wall_active_at_build[w] = walls_[w].active(time_);
  }
  lists_.time_at_build = time_;
  lists_.max_displacement = 0;
  ++rebuilds_;
}

void World::mark_step_ends() {
  const ParticleStore& p = particles_;
  const std::size_t owned = p.owned;
  ends_.kind.resize(owned);
  ends_.late.clear();
  ends_.inline_owner.clear();
  ends_.late_owner.clear();
  ends_.inline_owner_start.assign(lists_.pairs.slabs() + 1, 0);
  if (has_composites()) return;  // rigid bodies end their steps in a pass of their own
  // In parallel: the rebuild's serial parts keep the second thread waiting.
  const long n = static_cast<long>(owned);
  const long wall_rows = static_cast<long>(std::min(owned, lists_.walls.rows()));
  const long owners = static_cast<long>(lists_.ghosts.owners());
  const bool parallel = worth_parallel(owned);
#pragma omp parallel if (parallel)
  {
#pragma omp for schedule(static)
    for (long i = 0; i < n; ++i) {
      const bool late = i < wall_rows && lists_.walls.row_begin(i) != lists_.walls.row_end(i);
      ends_.kind[i] = late                       ? StepEndKind::late
                     : is_plain_sphere(p, i) ? StepEndKind::plain_sphere
                                             : StepEndKind::other;
    }
#pragma omp for schedule(static)
    for (long k = 0; k < owners; ++k) ends_.kind[lists_.ghosts.owner_at(k)] = StepEndKind::late;
  }
  // Particles with copies on other ranks wait for their forces from there (copies of copies
  // from a neighbour are that neighbour's to wait for).
  for (const std::uint32_t k : spread_.halo.sent_indices())
    if (k < owned + lists_.ghosts.count()) ends_.kind[k < owned ? k : lists_.ghosts.owner(k - owned)] = StepEndKind::late;
  for (std::size_t i = 0; i < owned; ++i)
    if (ends_.kind[i] == StepEndKind::late) ends_.late.push_back(static_cast<std::uint32_t>(i));

  // A slab ends once its rows and the previous slab's are done (World::pair_forces). Those rows
  // are all that touch a ghost in that slab: rows list their own slab and the next one up. So
  // an owner whose ghosts all share its slab can end with it, while its data is in cache; only
  // the images across the slab axis's faces wait for the whole pass. (With walls, every late
  // particle waits for the ghost fold and the wall forces instead: the lists stay empty.)
  if (!walls_.empty() || distributed()) return;
  std::size_t slab = 0;
  for (std::size_t k = 0; k < lists_.ghosts.owners(); ++k) {
    if (!lists_.ghosts.ghosts_share_layer(k, lists_.grid.slab_axis())) {
      ends_.late_owner.push_back(static_cast<std::uint32_t>(k));
      continue;
    }
    while (lists_.ghosts.owner_at(k) >= lists_.pairs.slab_end(slab)) ++slab;  // owners ascend, as do slabs
    ++ends_.inline_owner_start[slab + 1];
    ends_.inline_owner.push_back(static_cast<std::uint32_t>(k));
  }
  for (std::size_t s = 0; s + 1 < ends_.inline_owner_start.size(); ++s) ends_.inline_owner_start[s + 1] += ends_.inline_owner_start[s];
  // Images across the slab axis are made on its high side only, of particles within one
  // range of its low face: in the first slab, as cells are at least one range wide.
  ends_.late_owners_in_first_slab = true;
  for (const std::uint32_t k : ends_.late_owner)
    ends_.late_owners_in_first_slab &= lists_.pairs.slabs() > 0 && lists_.ghosts.owner_at(k) < lists_.pairs.slab_end(0);
}

Domain World::sub_domain_grid() const {
  // The box, as if periodic along its cut axes: the grid tiles it and keeps a layer on each
  // side for the halo. An end of a non-periodic axis is where the outermost particle is; along
  // the slab axis, of all ranks when other axes are cut too, so that the ranks of one slab cut
  // it into the same layers (which order the pairs across their cuts, pair_list.h).
  Domain d = settings_.domain;
  const RankGrid& ranks = spread_.ranks;
  const ParticleStore& p = particles_;
  for (const int a : ranks.stage_axes()) {
    double lo = ranks.axes[a].lo(), hi = ranks.axes[a].hi();
    double mn = std::numeric_limits<double>::infinity(), mx = -mn;
    for (std::size_t i = 0; i < p.owned; ++i) mn = std::min(mn, p.position[i][a]), mx = std::max(mx, p.position[i][a]);
    if (a == ranks.slab_axis && ranks.stage_axes().size() > 1) {
      mn = -ranks.comm->max(-mn);
      mx = ranks.comm->max(mx);
    }
    if (!std::isfinite(lo) || !std::isfinite(hi)) {
      if (!std::isfinite(lo)) lo = std::isfinite(mn) ? mn : (std::isfinite(hi) ? hi - 1 : 0.0);
      if (!std::isfinite(hi)) hi = std::isfinite(mx) ? std::max(mx, lo) : lo + 1;
      if (!(hi > lo)) hi = lo + 1e-9 * std::max(1.0, std::abs(lo));
    }
    d.lo[a] = lo;
    d.hi[a] = hi;
    d.periodic[a] = true;
  }
  return d;
}

}  // namespace talus
