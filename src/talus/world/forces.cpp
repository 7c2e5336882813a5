// The contact-force phase of World::step(): particle pairs by slab colouring, then walls.
#include <omp.h>

#include <algorithm>
#include <atomic>

#include "talus/world/memory_ref.h"
#include "talus/world/parallel.h"
#include "talus/world/sphere_pair_rows.h"
#include "talus/world/world.h"

namespace talus {

// Forces and torques arrive zeroed (by the drift and the ghost refresh, which touch every
// particle anyway); this pass only adds.
void World::compute_forces(double memory_dt) {
  ParticleStore& p = particles_;
  if (has_composites()) {
    {
      ScopedPhase phase(timer_, Phase::placement);
      shaped_.placed.place(p, shapes_);
    }
    with_tangential_model(settings_.tangential_model, [&](auto model) { composite_pair_forces<model.value>(memory_dt); });
  } else {
    with_tangential_model(settings_.tangential_model, [&](auto model) { pair_forces<model.value>(memory_dt); });
  }
  fold_ghost_forces();
  if (walls_.empty()) return;
  with_tangential_model(settings_.tangential_model, [&](auto model) { wall_forces<model.value>(memory_dt); });
}

void World::fold_ghost_forces() {
  if (distributed()) {
    ScopedPhase phase(timer_, Phase::exchange);
    spread_.halo.reverse(particles_);
  }
  lists_.ghosts.fold_forces(particles_);
}

double World::compute_forces_ending_step(double memory_dt, const StepEnd& end) {
  ParticleStore& p = particles_;
  double max_d2 = 0;
  with_tangential_model(settings_.tangential_model,
                        [&](auto model) { max_d2 = pair_forces<model.value>(memory_dt, &end); });
  if (walls_.empty() && !distributed()) {  // the owners of ghosts, the only late particles, ended in the pass
    ends_.ghosts_fresh = end.next_step;  // for move_to_next_step, which follows at once
    return max_d2;
  }
  fold_ghost_forces();
  if (!walls_.empty())
    with_tangential_model(settings_.tangential_model, [&](auto model) { wall_forces<model.value>(memory_dt); });
  ScopedPhase phase(timer_, Phase::integrate);
  return std::max(max_d2, end_step(p, ends_.late, end));
}

double World::end_owner_step(std::uint32_t k, const StepEnd& end) {
  ParticleStore& p = particles_;
  lists_.ghosts.fold_into_owner(p, k);
  const double d2 = end_step_of(p, lists_.ghosts.owner_at(k), end);
  lists_.ghosts.refresh_ghosts_of(p, k);
  return d2;
}

template <TangentialModel Model>
double World::pair_forces(double memory_dt, const StepEnd* end) {
  ScopedPhase phase(timer_, Phase::pair_forces);
  ParticleStore& p = particles_;
  const PairList& list = lists_.pairs;
  ContactMemory& mem = lists_.pairs.memory;
  const auto data = [](auto& v) { return v.empty() ? nullptr : v.data(); };
  const SpherePairArrays arrays{p.position.data(), p.velocity.data(), p.angular_velocity.data(), p.radius.data(),
                                p.inv_mass.data(), p.species.data(), list.neighbors(), list.row_offsets(),
                                p.force.data(), p.torque.data(), data(mem.spring), data(mem.normal_prev),
                                data(mem.rolling), lists_.pairs.remembered(), static_cast<std::uint32_t>(p.owned),
                                list.forward_reach()};
  const bool parallel = worth_parallel(p.owned);
  const std::vector<std::uint32_t>& chunk = list.slab_chunks();
  const long chunks = static_cast<long>(chunk.size()) - 1;
  const auto rows = with_memory_flags<Model>(mem, table_);
  // Chunk c writes to its own slabs and the first slab of chunk c + 1 only. Even chunks add
  // their rows first, then odd ones: an odd chunk waits for the even chunks on either side,
  // never for all of them, and the chunks depend on the list alone, never on the thread count
  // or the schedule, so every particle receives its contributions in the same order on any
  // team. With `end`, a slab's particles end their step once its rows and the previous slab's
  // are done (pairs within a slab point either way, to the next slab only forwards): at once,
  // except the first slab of an even chunk after the first, which the odd chunk before it
  // ends after writing to it, and the late particles (ghost owners, wall contacts).
  const StepEndKind* kind = ends_.kind.data();
  const auto end_slab = [&](std::uint32_t s) {
    double d2 = end_step(p, list.slab_begin(s), list.slab_begin(s + 1), *end, kind);
    for (std::uint32_t n = ends_.inline_owner_start[s]; n < ends_.inline_owner_start[s + 1]; ++n)
      d2 = std::max(d2, end_owner_step(ends_.inline_owner[n], *end));
    return d2;
  };
  const std::size_t chunk_count = static_cast<std::size_t>(std::max(chunks, 0L));
  std::vector<std::atomic<char>> claimed(chunk_count), done(chunk_count);
  const auto run_chunk = [&](long c) {
    double d2 = 0;
    if (c % 2 == 1) {  // the even chunks on either side first
      while (!done[c - 1].load(std::memory_order_acquire)) spin_pause();
      while (c + 1 < chunks && !done[c + 1].load(std::memory_order_acquire)) spin_pause();
    }
    for (std::uint32_t s = chunk[c]; s < chunk[c + 1]; ++s) {
      rows(arrays, table_, memory_dt, list.slab_begin(s), list.slab_begin(s + 1));
      const bool ended_later = c % 2 == 0 && c > 0 && s == chunk[c];
      if (end && !ended_later) d2 = std::max(d2, end_slab(s));
    }
    if (end && c % 2 == 1 && c + 1 < chunks) d2 = std::max(d2, end_slab(chunk[c + 1]));
    done[c].store(1, std::memory_order_release);
    return d2;
  };
  // Without walls the owners of ghosts across the slab axis's faces (World::ends_.late_owner) end
  // here too, once the rows that touch them and their images are done: those of the first
  // slab, which they lie in, and of the last, next to their images (mark_step_ends checks
  // that they lie in the first slab; if not, they wait for every chunk). Threads out of
  // chunks take them in blocks, which fills the wait for the last chunks.
  const bool owners_here = end && !ends_.late_owner.empty();
  std::atomic<std::size_t> next_owner{0};
  constexpr std::size_t kOwnerBlock = 64;
  const auto end_late_owners = [&] {
    double d2 = 0;
    for (long c = 0; c < chunks; ++c)
      if (c == 0 || c == chunks - 1 || !ends_.late_owners_in_first_slab)
        while (!done[c].load(std::memory_order_acquire)) spin_pause();
    for (;;) {
      const std::size_t from = next_owner.fetch_add(kOwnerBlock, std::memory_order_relaxed);
      if (from >= ends_.late_owner.size()) break;
      for (std::size_t n = from; n < std::min(from + kOwnerBlock, ends_.late_owner.size()); ++n)
        d2 = std::max(d2, end_owner_step(ends_.late_owner[n], *end));
    }
    return d2;
  };
  // Each thread starts on its own run of consecutive chunks, evens then odds, so that a chunk's
  // particles stay in one core's cache from step to step (taken by whichever thread was free,
  // they changed cores at random: the 4,400-sphere chute, whose data fits one core's cache,
  // spent 43 % more CPU on two threads than on one). The last chunk comes first among its
  // colour, so that the late owners are ready early. A thread done with its run takes what
  // is left of the others' from their ends, evens first. Evens never wait, and each thread
  // claims its own evens before anything else, so every wait ends.
  double max_d2 = 0;
#pragma omp parallel reduction(max : max_d2) if (parallel && chunks > 2)
  {
    const int team = omp_get_num_threads(), me = omp_get_thread_num();
    const auto first = [&](int t) { return chunks * t / team; };
    const auto take = [&](long c) {
      if (!claimed[c].exchange(1, std::memory_order_relaxed)) max_d2 = std::max(max_d2, run_chunk(c));
    };
    const long last = chunks - 1;
    for (int parity = 0; parity < 2; ++parity) {
      if (last % 2 == parity && first(me) <= last && last < first(me + 1)) take(last);
      for (long c = first(me); c < first(me + 1); ++c)
        if (c % 2 == parity) take(c);
    }
    for (int k = 1; k < team; ++k) {
      const int other = (me + k) % team;
      for (int parity = 0; parity < 2; ++parity)
        for (long c = first(other + 1) - 1; c >= first(other); --c)
          if (c % 2 == parity) take(c);
    }
    if (owners_here) max_d2 = std::max(max_d2, end_late_owners());
  }
  return max_d2;
}

template <TangentialModel Model>
void World::wall_forces(double memory_dt) {
  ScopedPhase phase(timer_, Phase::wall_forces);
  ParticleStore& p = particles_;
  WallContactList& list = lists_.walls;
  ContactMemory& mem = list.memory;
  const double t = time_;
  std::vector<Vec3> origin(walls_.size()), wall_velocity(walls_.size());
  std::vector<char> active(walls_.size());
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    origin[w] = walls_[w].origin_at(t);
    wall_velocity[w] = walls_[w].velocity_at(t);
    active[w] = walls_[w].active(t);
  }
  const std::size_t n = list.rows();
  constexpr std::size_t kRows = SubContactStore::kRowsPerBlock;
  const long blocks = static_cast<long>((n + kRows - 1) / kRows);
  const bool composites = has_composites();
  if (composites) shaped_.wall_points.follow(list);
  // Wall contacts crowd into the particles of a few cells (a pile's base, the gate): dynamic
  // chunks keep both threads busy. Each row writes only its own particle and each block of rows
  // its own contact points, so any schedule gives the same result.
#pragma omp parallel for schedule(dynamic, 4) if (worth_parallel(composites ? 16 * p.owned : p.owned))
  for (long block = 0; block < blocks; ++block) {
    const auto b = static_cast<std::size_t>(block);
    if (composites) shaped_.wall_points.start_block(b);
    for (std::size_t i = b * kRows; i < std::min(n, (b + 1) * kRows); ++i) {
      const bool fixed = p.inv_mass[i] == 0.0;  // fixed particles do not feel walls
      for (std::uint32_t e = list.row_begin(i); e < list.row_end(i); ++e) {
        const int w = list.wall(e);
        const Wall& wall = walls_[w];
        const double r = p.radius[i];
        const double gap = dot(p.position[i] - origin[w], wall.normal);
        list.force_on_wall[e] = {};
        if (p.shape[i] != 0) {
          if (fixed || !active[w] || gap >= r || (wall.bounded && gap < 0)) {
            shaped_.wall_points.forget(b, e);
            continue;
          }
          std::vector<SubContact>& points = shaped_.wall_points.next_points(b);
          const std::size_t first = points.size();
          const ContactResult res = composite_wall<Model>(i, wall, origin[w], wall_velocity[w], shaped_.wall_points.take(b, e),
                                                          points, memory_dt);
          shaped_.wall_points.record(e, first, points.size());
          p.force[i] += res.force_on_i;
          p.torque[i] += res.torque_i;
          list.force_on_wall[e] = -res.force_on_i;
          continue;
        }
        if (fixed) continue;
        SphereWallTouch touch;
        if (!active[w] || !sphere_touches_wall(wall, origin[w], p.position[i], r, touch)) {
          mem.clear(e);
          continue;
        }
        ContactGeometry g;
        g.normal = touch.normal;
        g.overlap = touch.overlap;
        g.arm_i = touch.normal * -(r - 0.5 * g.overlap);  // midpoint of the two deepest points (Huet et al. 2021, Fig. 2)
        g.inv_distance = touch.inv_distance;              // a rim's normal turns as the sphere goes round it
        const ContactMotion m{p.velocity[i], p.angular_velocity[i], wall_velocity[w], Vec3{}};
        const ContactHistoryRef h = memory_ref(mem, e);
        const ContactResult res = contact_force<Model>(g, m, table_.wall(p.species[i], wall.material),
                                                       1.0 / p.inv_mass[i], r, memory_dt, h);
        p.force[i] += res.force_on_i;
        p.torque[i] += res.torque_i;
        list.force_on_wall[e] = -res.force_on_i;
      }
    }
    if (composites) shaped_.wall_points.finish_block(b);
  }
  std::fill(wall_force_.begin(), wall_force_.end(), Vec3{});
  for (std::size_t e = 0; e < list.entries(); ++e) wall_force_[list.wall(e)] += list.force_on_wall[e];
  if (distributed()) {  // every rank knows the walls' totals (a gate's observer may read them)
    std::vector<double> total(3 * wall_force_.size());
    for (std::size_t w = 0; w < wall_force_.size(); ++w)
      for (int a = 0; a < 3; ++a) total[3 * w + a] = wall_force_[w][a];
    communicator().sum_in_place(total);
    for (std::size_t w = 0; w < wall_force_.size(); ++w) wall_force_[w] = {total[3 * w], total[3 * w + 1], total[3 * w + 2]};
  }
}

}  // namespace talus
