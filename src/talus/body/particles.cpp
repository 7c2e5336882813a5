#include "talus/body/particles.h"

#include <memory>

#include "talus/world/parallel.h"

namespace talus {

namespace {
// Gathers into `scratch`, then copies back: the arrays keep their memory (and capacity for the
// ghosts), and one scratch buffer serves every array instead of a fresh array each, whose
// pages the system would have to map and zero at every rebuild.
template <class T>
void permute(std::vector<T>& values, const std::vector<std::uint32_t>& order, unsigned char* scratch) {
  T* out = reinterpret_cast<T*>(scratch);
  const long n = static_cast<long>(order.size());
#pragma omp parallel if (worth_parallel(order.size()))
  {
#pragma omp for schedule(static)
    for (long k = 0; k < n; ++k) out[k] = values[order[k]];
#pragma omp for schedule(static)
    for (long k = 0; k < n; ++k) values[k] = out[k];
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
  static_assert(sizeof(Quat) >= sizeof(Vec3), "the scratch holds the largest element");
  const std::unique_ptr<unsigned char[]> scratch(new unsigned char[order.size() * sizeof(Quat)]);
  unsigned char* b = scratch.get();
  permute(position, order, b);
  permute(velocity, order, b);
  permute(angular_velocity, order, b);
  permute(force, order, b);
  permute(torque, order, b);
  permute(orientation, order, b);
  permute(radius, order, b);
  permute(inv_mass, order, b);
  permute(inv_inertia, order, b);
  permute(mass, order, b);
  permute(species, order, b);
  permute(shape, order, b);
  permute(gid, order, b);
}

void ParticleStore::push_ghost(std::size_t owner, const Vec3& shift) {
  position.push_back(position[owner] + shift);
  velocity.push_back(velocity[owner]);
  angular_velocity.push_back(angular_velocity[owner]);
  force.push_back({});
  torque.push_back({});
  orientation.push_back(orientation[owner]);
  radius.push_back(radius[owner]);
  inv_mass.push_back(inv_mass[owner]);
  inv_inertia.push_back(inv_inertia[owner]);
  mass.push_back(mass[owner]);
  species.push_back(species[owner]);
  shape.push_back(shape[owner]);
  gid.push_back(gid[owner]);
}

}  // namespace talus
