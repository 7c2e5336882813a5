#include "talus/body/particles.h"

#include <memory>

#include "talus/world/parallel.h"

namespace talus {

namespace {
// A permutation as its cycles (fixed points left out), each listed from its start: index[t + 1]
// is the old index whose value moves to index[t]. Applying it walks this list once with one
// saved value per cycle, so the arrays are reordered where they are, without a scratch copy
// (one would sit on top of everything a rebuild holds at that moment).
struct Cycles {
  std::vector<std::uint32_t> index;
  std::vector<std::uint32_t> end;  ///< one past the last position of each cycle in `index`
};

Cycles cycles_of(const std::vector<std::uint32_t>& order) {
  Cycles c;
  std::vector<char> seen(order.size(), 0);
  for (std::uint32_t k = 0; k < order.size(); ++k) {
    if (seen[k] || order[k] == k) continue;
    std::uint32_t j = k;
    do {
      c.index.push_back(j);
      seen[j] = 1;
      j = order[j];
    } while (j != k);
    c.end.push_back(static_cast<std::uint32_t>(c.index.size()));
  }
  return c;
}

template <class T>
void permute(std::vector<T>& values, const Cycles& c) {
  T* v = values.data();
  const std::uint32_t* index = c.index.data();
  std::uint32_t t = 0;
  for (const std::uint32_t end : c.end) {
    const T first = v[index[t]];
    for (; t + 1 < end; ++t) v[index[t]] = v[index[t + 1]];
    v[index[t]] = first;
    ++t;
  }
}
}  // namespace

void ParticleStore::resize(std::size_t n) {
  position.resize(n);
  velocity.resize(n);
  angular_velocity.resize(n);
  force.resize(n);
  torque.resize(n);
  orientation.resize(n);
  radius.resize(n);
  inv_mass.resize(n);
  inv_inertia.resize(n);
  mass.resize(n);
  species.resize(n);
  shape.resize(n);
  gid.resize(n);
}

void ParticleStore::reserve(std::size_t n) {
  position.reserve(n);
  velocity.reserve(n);
  angular_velocity.reserve(n);
  force.reserve(n);
  torque.reserve(n);
  orientation.reserve(n);
  radius.reserve(n);
  inv_mass.reserve(n);
  inv_inertia.reserve(n);
  mass.reserve(n);
  species.reserve(n);
  shape.reserve(n);
  gid.reserve(n);
}

void ParticleStore::permute_owned(const std::vector<std::uint32_t>& order) {
  resize(owned);
  const Cycles c = cycles_of(order);
  // The arrays are independent: the threads share them out.
  const int arrays = 13;
#pragma omp parallel for schedule(dynamic, 1) if (worth_parallel(order.size()))
  for (int a = 0; a < arrays; ++a) {
    switch (a) {
      case 0: permute(position, c); break;
      case 1: permute(velocity, c); break;
      case 2: permute(angular_velocity, c); break;
      case 3: permute(force, c); break;
      case 4: permute(torque, c); break;
      case 5: permute(orientation, c); break;
      case 6: permute(inv_inertia, c); break;
      case 7: permute(radius, c); break;
      case 8: permute(inv_mass, c); break;
      case 9: permute(mass, c); break;
      case 10: permute(species, c); break;
      case 11: permute(shape, c); break;
      default: permute(gid, c); break;
    }
  }
}

void ParticleStore::append_ghosts(const std::vector<std::uint32_t>& owner, const std::vector<Vec3>& shift) {
  const std::size_t first = size();
  resize(first + owner.size());
  const long n = static_cast<long>(owner.size());
#pragma omp parallel for schedule(static) if (worth_parallel(owner.size()))
  for (long g = 0; g < n; ++g) {
    const std::size_t k = first + g, o = owner[g];
    position[k] = position[o] + shift[g];
    velocity[k] = velocity[o];
    angular_velocity[k] = angular_velocity[o];
    orientation[k] = orientation[o];
    radius[k] = radius[o];
    inv_mass[k] = inv_mass[o];
    inv_inertia[k] = inv_inertia[o];
    mass[k] = mass[o];
    species[k] = species[o];
    shape[k] = shape[o];
    gid[k] = gid[o];
  }
}

}  // namespace talus
