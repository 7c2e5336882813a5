#include "talus/world/periodic_ghosts.h"

#include <omp.h>

#include <bit>

#include "talus/world/parallel.h"

namespace talus {

void PeriodicGhosts::create(ParticleStore& p, const Domain& domain, const CellGrid& grid, double band,
                            std::vector<CellCoord>& cell_of) {
  owner_.clear();
  shift_.clear();
  // First list the images (images of earlier images make the corners), then append them all
  // at once. Each axis is scanned in parallel blocks, each counting its images and then writing
  // them at its place, so the ghosts come in the order of a serial scan.
  std::vector<Vec3> image_position;
  for (int a = 0; a < 3; ++a) {
    if (!domain.periodic[a]) continue;
    const double length = domain.length(a);
    const std::size_t n = p.owned + owner_.size(), before = owner_.size();
    const auto position_of = [&](std::size_t k) { return k >= p.owned ? image_position[k - p.owned] : p.position[k]; };
    // A row lists its own slab and the next one up, never the one below the first slab: no
    // image there would ever be a neighbour.
    const bool low_side = a != grid.slab_axis();
    // Bit 0: an image on the low side (shifted by -length), bit 1: on the high side.
    const auto sides = [&](std::size_t k) {
      const double x = position_of(k)[a];
      return static_cast<unsigned>(low_side && domain.hi[a] - x < band) |
             (static_cast<unsigned>(x - domain.lo[a] < band) << 1);
    };
    const int threads = worth_parallel(n) ? omp_get_max_threads() : 1;
    std::vector<std::size_t> first(threads + 1, 0);
#pragma omp parallel num_threads(threads)
    {
      const int t = omp_get_thread_num(), team = omp_get_num_threads();
      const std::size_t lo = n * t / team, hi = n * (t + 1) / team;
      std::size_t images = 0;
      for (std::size_t k = lo; k < hi; ++k) images += std::popcount(sides(k));
      first[t + 1] = images;
#pragma omp barrier
#pragma omp single
      {
        for (int b = 0; b < team; ++b) first[b + 1] += first[b];
        const std::size_t total = before + first[team];
        owner_.resize(total);
        shift_.resize(total);
        image_position.resize(total);
        cell_of.resize(p.owned + total);
      }
      std::size_t out = before + first[t];
      for (std::size_t k = lo; k < hi; ++k) {
        const unsigned near = sides(k);
        if (near == 0) continue;
        const bool is_ghost = k >= p.owned;
        const std::uint32_t origin = is_ghost ? owner_[k - p.owned] : static_cast<std::uint32_t>(k);
        const Vec3 base_shift = is_ghost ? shift_[k - p.owned] : Vec3{};
        for (int side = -1; side <= 1; side += 2) {
          if (!(near & (side < 0 ? 1u : 2u))) continue;
          Vec3 shift = base_shift;
          shift[a] += side * length;
          CellCoord c = cell_of[k];
          c[a] += side * grid.cells(a);
          owner_[out] = origin;
          shift_[out] = shift;
          image_position[out] = p.position[origin] + shift;
          cell_of[p.owned + out] = c;
          ++out;
        }
      }
    }
  }
  // Room for an eighth more ghosts than now: growing the particle arrays copies each of them
  // (a transient the peak memory sees) and maps its pages afresh, so it should be rare.
  const std::size_t needed = p.owned + owner_.size();
  if (needed > p.position.capacity()) p.reserve(needed + owner_.size() / 8 + 64);
  p.append_ghosts(owner_, shift_);
  group_by_owner(p.owned);
}

void PeriodicGhosts::group_by_owner(std::size_t owned) {
  // A stable counting sort of the ghosts by owner.
  std::vector<std::uint32_t> first(owned + 1, 0);
  for (const std::uint32_t o : owner_) ++first[o + 1];
  for (std::size_t o = 0; o < owned; ++o) first[o + 1] += first[o];
  fold_owner_.clear();
  fold_start_.clear();
  for (std::size_t o = 0; o < owned; ++o) {
    if (first[o + 1] == first[o]) continue;
    fold_owner_.push_back(static_cast<std::uint32_t>(o));
    fold_start_.push_back(first[o]);
  }
  fold_start_.push_back(static_cast<std::uint32_t>(owner_.size()));
  fold_ghost_.resize(owner_.size());
  for (std::size_t g = 0; g < owner_.size(); ++g) fold_ghost_[first[owner_[g]]++] = static_cast<std::uint32_t>(g);
}

void PeriodicGhosts::update_positions(ParticleStore& p) const {
  const long n = static_cast<long>(owner_.size());
#pragma omp parallel for schedule(static) if (worth_parallel(owner_.size()))
  for (long g = 0; g < n; ++g) {
    const std::size_t k = p.owned + g;
    p.position[k] = p.position[owner_[g]] + shift_[g];
    p.orientation[k] = p.orientation[owner_[g]];
  }
}

void PeriodicGhosts::update_velocities(ParticleStore& p) const {
  const long n = static_cast<long>(owner_.size());
#pragma omp parallel for schedule(static) if (worth_parallel(owner_.size()))
  for (long g = 0; g < n; ++g) {
    const std::size_t k = p.owned + g;
    p.velocity[k] = p.velocity[owner_[g]];
    p.angular_velocity[k] = p.angular_velocity[owner_[g]];
  }
}

void PeriodicGhosts::refresh_ghost(ParticleStore& p, std::size_t g) const {
  const std::size_t k = p.owned + g;
  const std::uint32_t o = owner_[g];
  p.position[k] = p.position[o] + shift_[g];
  p.orientation[k] = p.orientation[o];
  p.velocity[k] = p.velocity[o];
  p.angular_velocity[k] = p.angular_velocity[o];
  p.force[k] = {};
  p.torque[k] = {};
}

void PeriodicGhosts::refresh(ParticleStore& p) const {
  const long n = static_cast<long>(owner_.size());
#pragma omp parallel for schedule(static) if (worth_parallel_ghost_pass(owner_.size()))
  for (long g = 0; g < n; ++g) refresh_ghost(p, g);
}

void PeriodicGhosts::fold_forces(ParticleStore& p) const {
  // Raw pointers: through the vectors, every store would make the compiler reload their data.
  Vec3* __restrict force = p.force.data();
  Vec3* __restrict torque = p.torque.data();
  const Vec3* __restrict ghost_force = force + p.owned;
  const Vec3* __restrict ghost_torque = torque + p.owned;
  if (omp_get_max_threads() == 1 || !worth_parallel_ghost_pass(fold_owner_.size())) {
    // Alone, ghost by ghost: the same sums in the same order, without the grouping's indirection.
    const std::uint32_t* __restrict owner = owner_.data();
    for (std::size_t g = 0; g < owner_.size(); ++g) {
      force[owner[g]] += ghost_force[g];
      torque[owner[g]] += ghost_torque[g];
    }
    return;
  }
  const long owners = static_cast<long>(fold_owner_.size());
  const std::uint32_t* __restrict grouped_owner = fold_owner_.data();
  const std::uint32_t* __restrict start = fold_start_.data();
  const std::uint32_t* __restrict ghost = fold_ghost_.data();
#pragma omp parallel for schedule(static)
  for (long k = 0; k < owners; ++k) {
    const std::uint32_t o = grouped_owner[k];
    for (std::uint32_t f = start[k]; f < start[k + 1]; ++f) {
      force[o] += ghost_force[ghost[f]];
      torque[o] += ghost_torque[ghost[f]];
    }
  }
}

void PeriodicGhosts::fold_into_owner(ParticleStore& p, std::size_t k) const {
  const std::uint32_t o = fold_owner_[k];
  for (std::uint32_t f = fold_start_[k]; f < fold_start_[k + 1]; ++f) {
    const std::size_t g = p.owned + fold_ghost_[f];
    p.force[o] += p.force[g];
    p.torque[o] += p.torque[g];
  }
}

void PeriodicGhosts::refresh_ghosts_of(ParticleStore& p, std::size_t k) const {
  for (std::uint32_t f = fold_start_[k]; f < fold_start_[k + 1]; ++f) refresh_ghost(p, fold_ghost_[f]);
}

bool PeriodicGhosts::ghosts_share_layer(std::size_t k, int axis) const {
  for (std::uint32_t f = fold_start_[k]; f < fold_start_[k + 1]; ++f)
    if (shift_[fold_ghost_[f]][axis] != 0) return false;
  return true;
}

}  // namespace talus
