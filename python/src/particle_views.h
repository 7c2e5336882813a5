#pragma once
// Read-only NumPy views of a running World's particle arrays (owned particles, not ghosts), with
// no copy. A view shows the state at the moment it was taken and stays valid for as long as
// Python holds it: before anything may move, reorder or reallocate the engine's arrays (a step,
// a list build), detach() hands the memory every live view shows over to those views and gives
// the engine a copy. A view that outlives a step thus costs the engine one copy of that array;
// one that is gone by then costs nothing.
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include <pybind11/numpy.h>

#include "talus/world/world.h"

namespace talus::python {

enum class ParticleField { position, velocity, angular_velocity, orientation, radius, mass, id, species };

class ParticleViews {
 public:
  // `engine` keeps the World alive while views of its memory exist.
  ParticleViews(World& world, std::shared_ptr<void> engine) : world_(world), engine_(std::move(engine)) {}

  pybind11::array view(ParticleField field);
  // Call before anything that may change the World's particle arrays.
  void detach();

 private:
  // What a view's memory belongs to: the engine's array, or the one detach() gave it.
  struct Owner {
    std::shared_ptr<void> memory;
  };
  World& world_;
  std::shared_ptr<void> engine_;
  std::vector<std::pair<ParticleField, std::weak_ptr<Owner>>> live_;
};

}  // namespace talus::python
