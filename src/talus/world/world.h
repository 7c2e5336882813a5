#pragma once
// The simulated system and its time step. World::step() reads as the pipeline:
// kick, drift, (rebuild | refresh ghosts), contact forces, kick.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "talus/analysis/snapshot.h"
#include "talus/body/particles.h"
#include "talus/contact/contact_law.h"
#include "talus/contact/contact_table.h"
#include "talus/integrate/velocity_verlet.h"
#include "talus/shape/composite_shape.h"
#include "talus/world/domain.h"
#include "talus/world/neighbor_lists.h"
#include "talus/world/phase_timer.h"
#include "talus/world/shaped_contacts.h"
#include "talus/world/spread_over_ranks.h"
#include "talus/world/step_end_plan.h"
#include "talus/world/sub_contacts.h"
#include "talus/world/wall.h"
#include "talus/world/world_state.h"

namespace talus {

// m: the recycle margin of a scenario with manifold contacts (contact.manifold_recycle). Ten
// micrometres of travel recycle about nine part pairs in ten in a resting or flowing cross pile.
inline constexpr double kDefaultManifoldRecycle = 1e-5;

// m: the margin a scenario gets unless it names one. Recycling needs the manifold and reuse, and
// a refit already moves the points each step, so it gets none.
inline constexpr double default_manifold_recycle(bool manifold, bool narrow_phase_reuse, double manifold_refit) {
  return manifold && narrow_phase_reuse && manifold_refit == 0 ? kDefaultManifoldRecycle : 0.0;
}

struct WorldSettings {
  Domain domain;
  Vec3 gravity{0, 0, -9.81};              ///< m/s^2; a tilted chute is tilted gravity
  double time_step = 1e-5;                ///< s
  double skin = 0;                        ///< m, neighbour-list skin; 0 picks 15 % of the largest diameter (measured best of 10, 15 and 20 % on the chute)
  TangentialModel tangential_model = TangentialModel::memory;
  // Face and edge contacts between convex parts as manifolds of up to 4 points, each carrying
  // k_n/n and eta_n/n of its manifold of n points; false: one point per part pair, as in
  // Huet et al. 2021, Sec. II B.
  bool contact_manifold = false;
  // Touching box pairs serve their contact from the feature of their last full SAT query while
  // the bodies' motion stays within that feature's reserve (box_pair_reuse.h). Exact: false
  // gives the same bits, slower; it exists for comparisons.
  bool narrow_phase_reuse = true;
  // With reuse, a face contact's points are refit from their features (box_box_refit) while the
  // two bodies have travelled less than this fraction of its deepest overlap since it was last
  // clipped: a point the clip would add meanwhile is missed, with an overlap below about twice
  // that fraction of the deepest. Off (0) by default: it is not exact, so a restart or another
  // rank count (whose budgets start afresh) no longer gives the same bits, and at the overlaps
  // of stiff grains (nanometres) the margin lasts a few steps and saves little.
  double manifold_refit = 0;
  // With reuse, a touching box pair (face or edge contact) serves its points from anchors fixed
  // in the two boxes when they were last computed, for this travel of the two bodies (m,
  // PlacedBodies::travel) since: each point's deepest points on the two boxes and the normal
  // move with their boxes, so the overlap follows the approach along the normal exactly and
  // sliding along the contact plane only to second order (the recycling of Box2D v3). A point
  // that the features would add meanwhile (a vertex coming down) is missed, and a restart or
  // another rank count no longer gives the same bits. Off (0) here; a scenario with manifold
  // contacts and reuse gets kDefaultManifoldRecycle unless it says otherwise.
  double manifold_recycle = 0;
  // One point per part pair: two touching box cores start GJK from last step's simplex
  // (box_simplex.h) instead of last step's normal; about half the narrow phase's time on a
  // resting column. The same distance and normal to GJK's tolerance, but where two faces lie
  // parallel the witness points (and so the contact point) are any pair over their overlap,
  // and the warm start keeps last step's pair where a cold start may pick another: not the same
  // bits as a cold start, but three dam breaks each way gave the same regimes and runouts within
  // their scatter (validation/REPORT.md), so it is on by default.
  bool gjk_warm_start = true;
  // Sphere worlds end each particle's step (closing half kick, next opening kick and drift)
  // inside the force pass, as soon as its force is complete; false runs them as separate passes
  // over all particles, the reference the fused form must equal to the bit.
  bool fused_step_end = true;
  // A run under mpirun builds its particles on rank 0 alone: every rank reads the scenario and
  // draws the same random placements, but only rank 0 keeps the particles (the others count
  // their global ids), and distribute() sends each rank its share. No rank but the first ever
  // holds more than its share of the system.
  bool particles_on_first_rank = false;
};

struct ParticleInit {
  Vec3 position, velocity, angular_velocity;
  Quat orientation;
  double radius = 0;   ///< m, bounding radius
  double mass = 0;     ///< kg
  Vec3 inertia;        ///< kg m^2, principal moments
  int species = 0;
  int shape = 0;
  bool fixed = false;
};

// What the run reports at each output step.
struct Diagnostics {
  double time = 0;
  double kinetic_translational = 0;  ///< J
  double kinetic_rotational = 0;     ///< J
  double elastic_normal = 0;         ///< J, sum of k_n delta_n^2 / 2
  double elastic_tangential = 0;     ///< J, sum of k_t |delta_t|^2 / 2
  double elastic_rolling = 0;        ///< J, sum of |M_k|^2 / (2 k_r)
  double gravitational = 0;          ///< J, -sum m g.x over mobile particles
  std::size_t contacts = 0;          ///< particle-particle contacts
  std::size_t wall_contacts = 0;
  double max_overlap_ratio = 0;      ///< largest delta_n / radius
  double max_speed = 0;              ///< m/s, largest translational speed
  double mean_speed = 0;             ///< m/s
  double max_angular_speed = 0;      ///< rad/s

  double elastic() const { return elastic_normal + elastic_tangential + elastic_rolling; }
  double kinetic() const { return kinetic_translational + kinetic_rotational; }
};

class World {
 public:
  explicit World(const WorldSettings& settings);

  // Setting up. Contact parameters must be set for every species (and wall material) in use.
  std::uint32_t add_particle(const ParticleInit& init);
  std::uint32_t add_sphere(const Vec3& position, double radius, double density, int species, bool fixed = false);
  int add_wall(const Wall& wall);
  // Room for n particles, so that adding them one by one does not double every array.
  void reserve_particles(std::size_t n);
  // Registers a rigid shape (parts in the body's principal frame); particles refer to it by index.
  // Index 0 is the sphere, whose radius each particle carries.
  int add_shape(const CompositeShape& shape);
  const std::vector<CompositeShape>& shapes() const { return shapes_; }
  // Contact points of non-spherical pairs and wall contacts, per list entry (empty for spheres).
  const SubContactStore& pair_sub_contacts() const { return shaped_.pair_points; }
  const SubContactStore& wall_sub_contacts() const { return shaped_.wall_points; }
  const WallContactList& wall_list() const { return lists_.walls; }
  ContactTable& contacts() { return table_; }
  const ContactTable& contacts() const { return table_; }

  // One time step; afterwards the state is complete (velocities at the end of the step).
  void step() { run(1); }
  // `steps` time steps, the same as `steps` calls of step(), bit for bit. Between two steps the
  // closing half kick of one and the opening half kick of the next share one pass over memory.
  void run(std::uint64_t steps);

  double time() const { return time_; }
  void set_time(double t) { time_ = t; }
  std::uint64_t step_count() const { return steps_; }
  const WorldSettings& settings() const { return settings_; }
  void set_gravity(const Vec3& g) { settings_.gravity = g; }
  void set_fused_step_end(bool on) { settings_.fused_step_end = on; }
  // Switching the model drops the contact memory the new one does not keep (Huet et al. 2021,
  // Sec. V B compares both on one packing).
  void set_tangential_model(TangentialModel m) { settings_.tangential_model = m; invalidate(); }
  const ParticleStore& particles() const { return particles_; }
  ParticleStore& particles_mutable() { invalidate(); return particles_; }
  const std::vector<Wall>& walls() const { return walls_; }
  std::vector<Wall>& walls_mutable() { invalidate(); return walls_; }
  /// N, total force of the particles on a wall at the last step (zero before the first)
  Vec3 wall_force(std::size_t wall) const { return wall < wall_force_.size() ? wall_force_[wall] : Vec3{}; }
  std::size_t owned_count() const { return particles_.owned; }
  std::size_t pair_entries() const { return lists_.pairs.entries(); }
  const PairList& pair_list() const { return lists_.pairs; }
  std::uint64_t rebuilds() const { return rebuilds_; }
  std::size_t memory_bytes() const;
  const PhaseTimer& timer() const { return timer_; }
  PhaseTimer& timer_mutable() { return timer_; }

  // Checkpoints (world_state.cpp). capture_state() first prepares a World that awaits its
  // set-up (particles added or walls changed since the last step); restore_state() puts a World
  // built from the same scenario back into a captured state, so that it steps on bit for bit.
  WorldState capture_state();
  // `ranks`: the ranks the run goes on over. A state gathered from as many ranks is spread over
  // them as it was, each rank replaying its last build, and goes on bit for bit; any other state
  // is restored whole (then distribute() spreads it, to round-off).
  void restore_state(WorldState state, const Communicator* ranks = nullptr);

  Diagnostics diagnostics() const;  ///< of the whole system, on every rank of a distributed world
  // Particles in global id order, contacts with their forces: the whole system, on every rank
  // of a distributed world.
  Snapshot snapshot() const;
  // The same on rank 0 alone, for the files it writes; the other ranks get no particles.
  Snapshot snapshot_on_first_rank() const;
  // This rank's part of the system, for output written piece by piece (.pvtu): its particles in
  // global id order, then the copies from other ranks that its contacts reach (so that each
  // contact line has both ends), contacts of the pairs it lists, named by record in the piece.
  struct SnapshotPiece {
    Snapshot snapshot;
    std::size_t owned = 0;  ///< the first `owned` records are this rank's particles
  };
  SnapshotPiece snapshot_piece() const;
  // Owned index of each global id (-1 if absent); valid until the next rebuild.
  std::vector<std::int32_t> index_of_gid() const;

  // Spreads the world over the ranks of `comm` on a grid of `counts` ranks along x, y and z
  // (rank_grid.h; zeros: RankGrid::choose_counts picks them), each rank keeping the particles
  // of its box; `slab_axis`, a cut axis, is the pair list's (-1: the one its slabs would hold
  // most evenly, if cut). Every rank must hold the same whole system when it calls this, or,
  // for a world built with WorldSettings::particles_on_first_rank, rank 0 the whole system and
  // the others none. One rank along a periodic axis makes its own images there.
  void distribute(const Communicator& comm, RankCounts counts = {0, 0, 0}, int slab_axis = -1);
  // The same with the cuts given (each slab at least an interaction range wide).
  void distribute(const RankGrid& ranks);
  void balance_ranks_by(RankGrid::Balance balance) { spread_.ranks.balance = balance; }
  bool distributed() const { return spread_.ranks.comm != nullptr; }
  const RankGrid& rank_grid() const { return spread_.ranks; }
  const HaloExchange& halo() const { return spread_.halo; }
  const Communicator& communicator() const;  ///< the ranks of a distributed world, else one rank
  std::uint64_t particles_moved_between_ranks() const { return spread_.migrated; }

  // Builds the lists and computes the forces now if the set-up changed since the last step
  // (particles added or removed, walls changed) instead of at the next step, which then finds
  // them done: diagnostics() and snapshot() of such a World otherwise see no contacts.
  void make_ready() {
    if (!ready_) prepare();
  }
  // Insertion into a distributed world runs alike on every rank, each adding the particles it
  // owns (`owns`) and passing over the others' ids, so that ids stay global and unique.
  bool owns(const Vec3& position) const;
  void skip_global_id() {
    ++next_gid_;
    invalidate();
  }
  // Particles added since the start, on every rank (the next global id).
  std::uint32_t particles_added() const { return next_gid_; }
  // The lists are built anew before the next step (on every rank of a distributed world, which
  // must all ask: particles left some rank).
  void rebuild_before_next_step() { invalidate(); }
  // Drops every owned particle for which `remove(index)` is true; returns how many. The contact
  // memories of the others survive: the next step's rebuild carries them over by global id.
  template <class Pred>
  std::size_t remove_particles_if(Pred remove);

 private:
  void invalidate() { ready_ = false; }
  void prepare();
  void open_step(int opening_kicks);  ///< the kicks and drift that open a step, then move_to_next_step
  void move_to_next_step();           ///< the clock, and the list rebuilt or the ghosts refreshed
  // How each particle's step ends (compute_forces_ending_step): late for those whose force is
  // complete only after the ghost fold and the walls. Set at every rebuild.
  void mark_step_ends();
  void rebuild();
  bool needs_rebuild() const;
  void compute_forces(double memory_dt);
  // Sphere worlds: the forces, each particle's step ended (StepEnd) as soon as its force is
  // complete; returns the largest squared drift from the positions at the last build.
  double compute_forces_ending_step(double memory_dt, const StepEnd& end);
  template <TangentialModel Model> double pair_forces(double memory_dt, const StepEnd* end = nullptr);
  // Folds the ghost forces of owner k (lists_.ghosts.owner_at numbering), ends its step, refreshes
  // its ghosts; returns its squared travel since the build.
  double end_owner_step(std::uint32_t k, const StepEnd& end);
  template <TangentialModel Model> void wall_forces(double memory_dt);
  template <TangentialModel Model> void composite_pair_forces(double memory_dt);
  template <TangentialModel Model, bool kProfile>
  ContactResult composite_pair(std::size_t i, std::size_t j, std::span<const SubContact> previous,
                               std::vector<SubContact>& contacts, double memory_dt, double travelled,
                               PartBudget* part_budgets, double& gap);
  template <TangentialModel Model>
  ContactResult composite_wall(std::size_t i, const Wall& wall, const Vec3& origin, const Vec3& wall_velocity,
                               std::span<const SubContact> previous, std::vector<SubContact>& contacts,
                               double memory_dt);
  bool has_composites() const;
  // The ghost forces handed back: those of ghosts from other ranks to their originals there,
  // then those of periodic images to their owners here.
  void fold_ghost_forces();
  std::size_t integration_cost() const;  ///< per particle, in sphere updates (velocity_verlet.h)
  double interaction_range() const;
  double particle_skin(double largest_radius) const;  ///< m, the list's skin
  // The grid distribute() cuts the system this rank holds whole into.
  RankGrid grid_for_whole_system(const Communicator& comm, RankCounts counts, int slab_axis) const;
  Domain sub_domain_grid() const;         ///< what this rank's grid covers in a distributed world
  Diagnostics local_diagnostics() const;  ///< of this rank's particles and the pairs it lists
  // How a snapshot of this rank names the partners of its contacts: by record (one rank), by
  // global id (a piece that gather_snapshot joins), or by record with the ghosts from the rank
  // above appended as records (snapshot_piece).
  enum class PartnerNames { kRecord, kGlobalId, kRecordWithGhosts };
  Snapshot local_snapshot(PartnerNames names, std::size_t* owned_records = nullptr) const;
  void restore_by_global_ids(const WorldState& state);           ///< restore_state of a state gathered from ranks
  void replay_last_build(const WorldState& state);               ///< restore_state of one rank's state
  void take_state_without_lists(const WorldState& state);        ///< the particles and counters; lists emptied
  MemoryLayout memory_layout() const;

  WorldSettings settings_;
  ParticleStore particles_;
  std::vector<Wall> walls_;
  std::vector<Vec3> wall_force_;
  ContactTable table_;
  std::vector<CompositeShape> shapes_ = std::vector<CompositeShape>(1);
  NeighborLists lists_;     ///< cells, pair and wall lists with their memories, periodic images
  ShapedContacts shaped_;   ///< contact points and scratch of rigid bodies of several parts
  SpreadOverRanks spread_;  ///< this rank's box and halo (ranks.comm == nullptr: not distributed)
  StepEndPlan ends_;        ///< how each particle's step ends in the force pass (sphere worlds)
  double time_ = 0;
  std::uint64_t steps_ = 0;
  std::uint64_t rebuilds_ = 0;
  std::uint32_t next_gid_ = 0;
  bool ready_ = false;
  PhaseTimer timer_;
};

template <class Pred>
std::size_t World::remove_particles_if(Pred remove) {
  // A permutation of all owned particles: the kept ones first, in their order, then the removed
  // ones, which the resize drops.
  std::vector<std::uint32_t> order, removed;
  for (std::size_t i = 0; i < particles_.owned; ++i)
    (remove(i) ? removed : order).push_back(static_cast<std::uint32_t>(i));
  if (removed.empty()) return 0;
  const std::size_t kept = order.size();
  order.insert(order.end(), removed.begin(), removed.end());
  particles_.permute_owned(order);  // drops the ghosts
  particles_.owned = kept;
  particles_.resize(kept);
  // The lists stay as built: rebuild() carries their memories by the global ids of that build
  // (lists_.gid_at_build), and the entries of removed particles find no place in the new lists.
  invalidate();
  return removed.size();
}

}  // namespace talus
