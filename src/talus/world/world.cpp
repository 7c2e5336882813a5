// A World: particles, shapes and walls added; the stages of the step in order (World::run).
#include "talus/world/world.h"

#include <malloc.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "talus/integrate/velocity_verlet.h"

namespace talus {

namespace {
// Large arrays come straight from the system (mmap) and go back to it when freed. Left alone,
// glibc raises its mmap threshold at the first such free, and the arrays that every neighbour
// rebuild allocates and frees then stay resident in the heap (a third of the peak memory of
// the 32,000-particle chute). Smaller ones come from the heap, whose top is kept up to 32 MiB:
// a rebuild's scratch arrays of a few hundred kilobytes, freed at the top, would otherwise go
// back to the system at each rebuild and have their pages mapped again at the next.
void return_large_arrays_to_system() {
  static const bool done = [] {
    return mallopt(M_MMAP_THRESHOLD, 256 * 1024) == 1 && mallopt(M_TRIM_THRESHOLD, 32 * 1024 * 1024) == 1;
  }();
  (void)done;
}
}  // namespace

World::World(const WorldSettings& settings) : settings_(settings) { return_large_arrays_to_system(); }

std::uint32_t World::add_particle(const ParticleInit& init) {
  if (!(init.radius > 0)) throw std::invalid_argument("particle radius must be positive");
  if (!(init.mass > 0)) throw std::invalid_argument("particle mass must be positive");
  if (next_gid_ == std::numeric_limits<std::uint32_t>::max())  // the id GidIndex keeps for empty slots
    throw std::length_error("more than 2^32 - 1 particles added to one run");
  if (settings_.particles_on_first_rank && Communicator::world().rank() != 0) {
    skip_global_id();  // rank 0 keeps it, and hands it over in distribute()
    return next_gid_ - 1;
  }
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

void World::reserve_particles(std::size_t n) {
  if (!settings_.particles_on_first_rank || Communicator::world().rank() == 0) particles_.reserve(n);
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
  return 2 * communicator().max(r_max) + lists_.skin;
}

const Communicator& World::communicator() const {
  return distributed() ? *spread_.ranks.comm : Communicator::alone();
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
  lists_.skin = particle_skin(communicator().max(r_max));
  wall_force_.assign(walls_.size(), Vec3{});
  rebuild();
  std::fill(particles_.force.begin(), particles_.force.end(), Vec3{});
  std::fill(particles_.torque.begin(), particles_.torque.end(), Vec3{});
  compute_forces(0.0);  // forces at t0; memories do not advance
  ready_ = true;
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
    end.position_at_build = lists_.position_at_build.data();
    const double max_d2 = compute_forces_ending_step(dt, end);
    ++steps_;
    if (end.next_step) {
      lists_.max_displacement = std::sqrt(max_d2);
      move_to_next_step();
    }
  }
}

void World::open_step(int opening_kicks) {
  const double dt = settings_.time_step;
  {
    ScopedPhase phase(timer_, Phase::integrate);
    // Also zeroes the owned forces: the kicks were their last readers.
    lists_.max_displacement = std::sqrt(kick_drift(particles_, opening_kicks, 0.5 * dt, dt, settings_.gravity,
                                             lists_.position_at_build, integration_cost()));
  }
  move_to_next_step();
}

void World::move_to_next_step() {
  time_ += settings_.time_step;
  bool rebuild_now = needs_rebuild();
  if (distributed()) {
    ScopedPhase vote(timer_, Phase::rebuild_vote);
    rebuild_now = communicator().any(rebuild_now);
  }
  if (rebuild_now) {
    rebuild();  // new ghosts copy the current state, with zero forces
  } else {
    if (!ends_.ghosts_fresh) lists_.ghosts.refresh(particles_);
    if (distributed()) {  // after the periodic images, which the rank below may hold copies of
      ScopedPhase exchange(timer_, Phase::exchange);
      spread_.halo.forward(particles_);
    }
  }
  ends_.ghosts_fresh = false;
}

std::vector<std::int32_t> World::index_of_gid() const {
  std::vector<std::int32_t> index(next_gid_, -1);
  for (std::size_t i = 0; i < particles_.owned; ++i) index[particles_.gid[i]] = static_cast<std::int32_t>(i);
  return index;
}

std::size_t World::memory_bytes() const {
  const ParticleStore& p = particles_;
  const std::size_t per_particle = 6 * sizeof(Vec3) + sizeof(Quat) + 3 * sizeof(double) + 3 * 4;
  return p.position.capacity() * per_particle + lists_.pairs.bytes() + lists_.carried.bytes() +
         lists_.cell_of.capacity() * sizeof(CellCoord) + lists_.position_at_build.capacity() * sizeof(Vec3) +
         ends_.kind.capacity() +
         (ends_.late.capacity() + ends_.inline_owner.capacity() + ends_.inline_owner_start.capacity() + ends_.late_owner.capacity()) *
             sizeof(std::uint32_t);
}

}  // namespace talus
