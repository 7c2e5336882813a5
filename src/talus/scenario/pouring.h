#pragma once
// Pouring: batches of particles inserted at random free places of a region while the run goes
// on, until a total count is reached.
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include <nlohmann/json.hpp>

#include "talus/world/world.h"

namespace talus {

struct PourSpec {
  int species = 0;
  double density = 0;            ///< kg/m^3
  double radius_min = 0, radius_max = 0;  ///< m
  Vec3 region_lo, region_hi;     ///< m
  Vec3 velocity;                 ///< m/s, initial velocity of poured particles
  std::size_t total = 0;         ///< particles to pour in all
  std::size_t batch = 0;         ///< tried per pouring event
  double interval = 0;           ///< s between events
  double start_time = 0;         ///< s
  bool rigid = false;            ///< non-spherical: copies of `prototype` at random orientations
  ParticleInit prototype;
};

class Pouring {
 public:
  Pouring(PourSpec spec, std::uint64_t seed) : spec_(spec), rng_(seed) {}
  // Inserts the batches that are due at the world's time; returns how many were added.
  std::size_t pour_due(World& world);
  bool done() const { return poured_ >= spec_.total; }
  // Time of the next batch (infinity when done): pour_due adds it once the world has reached it.
  double next_time() const {
    return done() ? std::numeric_limits<double>::infinity() : next_time_ < 0 ? spec_.start_time : next_time_;
  }
  std::size_t poured() const { return poured_; }
  std::size_t total() const { return spec_.total; }
  // Checkpoints (pouring_state.cpp): the random generator, the count poured, the next event.
  nlohmann::json state() const;
  void restore(const nlohmann::json& state);

 private:
  PourSpec spec_;
  std::mt19937_64 rng_;
  std::size_t poured_ = 0;
  double next_time_ = -1;
};

}  // namespace talus
