#include "particle_views.h"

#include <algorithm>
#include <type_traits>

namespace talus::python {

namespace py = pybind11;

// The views read Vec3 and Quat arrays as rows of doubles.
static_assert(sizeof(Vec3) == 3 * sizeof(double) && std::is_standard_layout_v<Vec3>);
static_assert(sizeof(Quat) == 4 * sizeof(double) && std::is_standard_layout_v<Quat>);

namespace {

// The World's own arrays, changed in place without telling it: detach() leaves every value as
// it was and moves only the memory. particles_mutable() would have the World build its lists
// again before the next step, one build earlier than otherwise, which changes the run's
// round-off from there on.
ParticleStore& store_of(World& world) { return const_cast<ParticleStore&>(world.particles()); }

// `values` now in new memory of the same capacity (so that ghosts appended later do not
// reallocate it sooner than the engine's own would be); the old memory, unchanged, returned.
template <class T>
std::shared_ptr<void> take_memory(std::vector<T>& values) {
  auto kept = std::make_shared<std::vector<T>>(std::move(values));  // leaves `values` empty
  values.reserve(kept->capacity());
  values.assign(kept->begin(), kept->end());
  return kept;
}

std::shared_ptr<void> take_memory(ParticleStore& p, ParticleField field) {
  switch (field) {
    case ParticleField::position: return take_memory(p.position);
    case ParticleField::velocity: return take_memory(p.velocity);
    case ParticleField::angular_velocity: return take_memory(p.angular_velocity);
    case ParticleField::orientation: return take_memory(p.orientation);
    case ParticleField::radius: return take_memory(p.radius);
    case ParticleField::mass: return take_memory(p.mass);
    case ParticleField::id: return take_memory(p.gid);
    case ParticleField::species: return take_memory(p.species);
  }
  return {};
}

// Rows of `columns` values of type S (none: a flat array).
template <class S>
py::array rows(const void* data, std::size_t n, std::size_t columns, py::handle base) {
  const auto item = static_cast<py::ssize_t>(sizeof(S));
  if (columns == 0) return py::array_t<S>({static_cast<py::ssize_t>(n)}, {item}, static_cast<const S*>(data), base);
  const auto c = static_cast<py::ssize_t>(columns);
  return py::array_t<S>({static_cast<py::ssize_t>(n), c}, {c * item, item}, static_cast<const S*>(data), base);
}

}  // namespace

py::array ParticleViews::view(ParticleField field) {
  std::erase_if(live_, [](const auto& entry) { return entry.second.expired(); });
  auto owner = std::make_shared<Owner>(Owner{engine_});
  live_.emplace_back(field, owner);
  // The array's base holds the owner: the memory lives as long as the array and its slices.
  py::capsule base(new std::shared_ptr<Owner>(std::move(owner)),
                   [](void* p) { delete static_cast<std::shared_ptr<Owner>*>(p); });
  const ParticleStore& p = world_.particles();
  const std::size_t n = p.owned;
  py::array a;
  switch (field) {
    case ParticleField::position: a = rows<double>(p.position.data(), n, 3, base); break;
    case ParticleField::velocity: a = rows<double>(p.velocity.data(), n, 3, base); break;
    case ParticleField::angular_velocity: a = rows<double>(p.angular_velocity.data(), n, 3, base); break;
    case ParticleField::orientation: a = rows<double>(p.orientation.data(), n, 4, base); break;
    case ParticleField::radius: a = rows<double>(p.radius.data(), n, 0, base); break;
    case ParticleField::mass: a = rows<double>(p.mass.data(), n, 0, base); break;
    case ParticleField::id: a = rows<std::uint32_t>(p.gid.data(), n, 0, base); break;
    case ParticleField::species: a = rows<std::int32_t>(p.species.data(), n, 0, base); break;
  }
  a.attr("setflags")(py::arg("write") = false);
  return a;
}

void ParticleViews::detach() {
  ParticleStore& p = store_of(world_);
  for (std::size_t k = 0; k < live_.size(); ++k) {
    if (live_[k].second.expired()) continue;
    const ParticleField field = live_[k].first;
    const std::shared_ptr<void> memory = take_memory(p, field);
    // Every live view of this field shows the same memory: all of them take it.
    for (std::size_t l = k; l < live_.size(); ++l)
      if (live_[l].first == field)
        if (const std::shared_ptr<Owner> owner = live_[l].second.lock()) {
          owner->memory = memory;
          live_[l].second.reset();
        }
  }
  live_.clear();
}

}  // namespace talus::python
