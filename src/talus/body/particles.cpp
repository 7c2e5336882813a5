#include "talus/body/particles.h"

namespace talus {

namespace {
template <class T>
void permute(std::vector<T>& values, const std::vector<std::uint32_t>& order) {
  std::vector<T> out(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) out[k] = values[order[k]];
  values.swap(out);
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
  permute(position, order);
  permute(velocity, order);
  permute(angular_velocity, order);
  permute(force, order);
  permute(torque, order);
  permute(orientation, order);
  permute(radius, order);
  permute(inv_mass, order);
  permute(inv_inertia, order);
  permute(mass, order);
  permute(species, order);
  permute(shape, order);
  permute(gid, order);
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
