// World::capture_state and World::restore_state: the one place that knows which members make
// up the state of a World (see world_state.h for why the lists are rebuilt, not stored).
#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

#include "talus/world/world.h"

namespace talus {

namespace {

ParticleStore owned_copy(const ParticleStore& p) {
  ParticleStore out = p;
  out.drop_ghosts();
  return out;
}

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument(what);
}

void check_memory_size(const ContactMemory& stored, const ContactMemory& rebuilt, const char* list) {
  require(stored.spring.size() == rebuilt.spring.size() && stored.normal_prev.size() == rebuilt.normal_prev.size() &&
              stored.rolling.size() == rebuilt.rolling.size(),
          std::string(list) + " contact memory does not fit the scenario's contact model");
}

void check_particles(const ParticleStore& p, int species, std::size_t shapes, std::uint32_t next_gid) {
  const std::size_t n = p.owned;
  require(p.size() == n && p.velocity.size() == n && p.angular_velocity.size() == n && p.force.size() == n &&
              p.torque.size() == n && p.orientation.size() == n && p.radius.size() == n && p.inv_mass.size() == n &&
              p.inv_inertia.size() == n && p.mass.size() == n && p.species.size() == n && p.shape.size() == n &&
              p.gid.size() == n,
          "particle arrays of different lengths");
  for (std::size_t i = 0; i < n; ++i) {
    require(p.species[i] >= 0 && p.species[i] < species, "particle species " + std::to_string(p.species[i]) +
                                                             " not in the scenario (" + std::to_string(species) +
                                                             " species)");
    require(p.shape[i] >= 0 && static_cast<std::size_t>(p.shape[i]) < shapes,
            "particle shape " + std::to_string(p.shape[i]) + " not in the scenario");
    require(p.gid[i] < next_gid, "particle global id beyond the next free id");
  }
  // Memories find their particles by global id: two particles with one id would swap them.
  // (Sorted, not flagged per id: a rank's share must not cost a byte per particle of the run.)
  std::vector<std::uint32_t> ids(p.gid.begin(), p.gid.begin() + static_cast<std::ptrdiff_t>(n));
  std::sort(ids.begin(), ids.end());
  const auto twice = std::adjacent_find(ids.begin(), ids.end());
  require(twice == ids.end(), twice == ids.end() ? "" : "two particles share the global id " + std::to_string(*twice));
}

// Appends the vectors' values to `out`, each after its length.
struct StatePacker {
  ByteWriter w;
  template <class T> void put(const std::vector<T>& v) {
    w.put(static_cast<std::uint64_t>(v.size()));
    for (const T& x : v) w.put(x);
  }
};

template <class T>
void take(ByteReader& r, std::vector<T>& v) {
  for (auto n = r.get<std::uint64_t>(); n > 0; --n) v.push_back(r.get<T>());
}

void put_lists(StatePacker& out, const std::vector<SubContactList>& lists) {
  out.w.put(static_cast<std::uint64_t>(lists.size()));
  for (const SubContactList& l : lists) out.put(l);
}

void take_lists(ByteReader& r, std::vector<SubContactList>& lists) {
  for (auto n = r.get<std::uint64_t>(); n > 0; --n) take(r, lists.emplace_back());
}

// The pieces of every rank joined, rank after rank, on rank 0; the other ranks keep their own
// piece (WorldState::whole).
void join_pieces(WorldState& s, const Communicator& comm) {
  std::vector<std::byte> mine;
  StatePacker out{ByteWriter(mine)};
  const ParticleStore& p = s.particles;
  out.put(p.position), out.put(p.velocity), out.put(p.angular_velocity), out.put(p.force), out.put(p.torque);
  out.put(p.orientation), out.put(p.radius), out.put(p.inv_mass), out.put(p.inv_inertia), out.put(p.mass);
  out.put(p.species), out.put(p.shape), out.put(p.gid), out.put(s.position_at_build);
  out.put(s.pair_gid_i), out.put(s.pair_gid_j);
  out.put(s.pair_memory.spring), out.put(s.pair_memory.normal_prev), out.put(s.pair_memory.rolling);
  out.put(s.wall_gid), out.put(s.wall_index), out.put(s.wall_entry_force);
  out.put(s.wall_memory.spring), out.put(s.wall_memory.normal_prev), out.put(s.wall_memory.rolling);
  put_lists(out, s.pair_sub), put_lists(out, s.wall_sub);
  const std::vector<std::byte> all = comm.gather(mine, 0);
  s.ranks = static_cast<std::uint64_t>(comm.size());
  if (comm.rank() != 0) {
    s.whole = false;
    return;
  }
  WorldState j;
  ParticleStore& q = j.particles;
  ByteReader in(all);
  WorldState::RankLayout& layout = s.layout;
  const auto share = [](std::vector<std::uint64_t>& shares, std::size_t before, std::size_t after) {
    shares.push_back(after - before);
  };
  while (!in.done()) {
    const std::size_t particles = q.position.size(), pairs = j.pair_gid_i.size(), walls = j.wall_gid.size();
    take(in, q.position), take(in, q.velocity), take(in, q.angular_velocity), take(in, q.force), take(in, q.torque);
    take(in, q.orientation), take(in, q.radius), take(in, q.inv_mass), take(in, q.inv_inertia), take(in, q.mass);
    take(in, q.species), take(in, q.shape), take(in, q.gid), take(in, j.position_at_build);
    take(in, j.pair_gid_i), take(in, j.pair_gid_j);
    take(in, j.pair_memory.spring), take(in, j.pair_memory.normal_prev), take(in, j.pair_memory.rolling);
    take(in, j.wall_gid), take(in, j.wall_index), take(in, j.wall_entry_force);
    take(in, j.wall_memory.spring), take(in, j.wall_memory.normal_prev), take(in, j.wall_memory.rolling);
    take_lists(in, j.pair_sub), take_lists(in, j.wall_sub);
    share(layout.particles, particles, q.position.size());
    share(layout.pair_entries, pairs, j.pair_gid_i.size());
    share(layout.wall_entries, walls, j.wall_gid.size());
  }
  q.owned = q.position.size();
  s.particles = std::move(q);
  s.position_at_build = std::move(j.position_at_build);
  s.pair_gid_i = std::move(j.pair_gid_i);
  s.pair_gid_j = std::move(j.pair_gid_j);
  s.pair_memory = std::move(j.pair_memory);
  s.wall_gid = std::move(j.wall_gid);
  s.wall_index = std::move(j.wall_index);
  s.wall_entry_force = std::move(j.wall_entry_force);
  s.wall_memory = std::move(j.wall_memory);
  s.pair_sub = std::move(j.pair_sub);
  s.wall_sub = std::move(j.wall_sub);
}

}  // namespace

WorldState World::capture_state() {
  if (!ready_) prepare();
  WorldState s;
  s.particles = owned_copy(particles_);
  s.next_gid = next_gid_;
  s.time = time_;
  s.steps = steps_;
  s.rebuilds = rebuilds_;
  s.gravity = settings_.gravity;
  s.tangential_model = settings_.tangential_model;
  s.walls = walls_;
  s.wall_force = wall_force_;
  s.position_at_build = lists_.position_at_build;
  s.time_at_build = lists_.time_at_build;
  s.skin = lists_.skin;

  const std::vector<std::uint32_t>& gid = particles_.gid;
  for (std::size_t i = 0; i < lists_.pairs.rows(); ++i)
    for (std::uint32_t e = lists_.pairs.row_begin(i); e < lists_.pairs.row_end(i); ++e) {
      s.pair_gid_i.push_back(gid[i]);
      s.pair_gid_j.push_back(gid[lists_.pairs.neighbor(e)]);
    }
  s.pair_memory = lists_.pairs.memory;
  s.pair_sub = shaped_.pair_points.lists();
  for (std::size_t i = 0; i < lists_.walls.rows(); ++i)
    for (std::uint32_t e = lists_.walls.row_begin(i); e < lists_.walls.row_end(i); ++e) {
      s.wall_gid.push_back(gid[i]);
      s.wall_index.push_back(lists_.walls.wall(e));
    }
  s.wall_memory = lists_.walls.memory;
  s.wall_entry_force = lists_.walls.force_on_wall;
  s.wall_sub = shaped_.wall_points.lists();
  if (distributed()) {
    const RankGrid& grid = spread_.ranks;
    s.layout.axis = grid.slab_axis;
    s.layout.rebalance = grid.axes[grid.slab_axis].rebalance;
    s.layout.min_width = grid.axes[grid.slab_axis].min_width;
    for (const int a : grid.stage_axes()) s.layout.cut[a] = grid.axes[a].cut;
    join_pieces(s, communicator());
  }
  return s;
}

namespace {

// Cuts a state joined rank after rank (WorldState::layout) down to rank r's share, in place: a
// copy of the joined state would double a restart's peak memory.
void keep_share_of_rank(WorldState& share, int r) {
  if (share.share_of_rank >= 0) {  // read as this share alone
    require(share.share_of_rank == r, "a state read as rank " + std::to_string(share.share_of_rank) +
                                          "'s share restored on rank " + std::to_string(r));
    share.ranks = 1;
    share.layout = {};
    share.share_of_rank = -1;
    return;
  }
  const WorldState::RankLayout l = share.layout;
  const auto start = [r](const std::vector<std::uint64_t>& shares) {
    return std::accumulate(shares.begin(), shares.begin() + r, std::uint64_t{0});
  };
  const auto slice = [](auto& v, std::uint64_t from, std::uint64_t count) {
    if (v.empty()) return;  // an array the run does not keep (memories of a model, shapes' points)
    require(from + count <= v.size(), "a rank's share runs past the stored arrays");
    std::rotate(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(from), v.end());
    v.resize(count);
    v.shrink_to_fit();
  };
  const std::uint64_t p0 = start(l.particles), pn = l.particles[r];
  ParticleStore& p = share.particles;
  slice(p.position, p0, pn), slice(p.velocity, p0, pn), slice(p.angular_velocity, p0, pn), slice(p.force, p0, pn);
  slice(p.torque, p0, pn), slice(p.orientation, p0, pn), slice(p.radius, p0, pn), slice(p.inv_mass, p0, pn);
  slice(p.inv_inertia, p0, pn), slice(p.mass, p0, pn), slice(p.species, p0, pn), slice(p.shape, p0, pn);
  slice(p.gid, p0, pn), slice(share.position_at_build, p0, pn);
  p.owned = pn;
  const std::uint64_t e0 = start(l.pair_entries), en = l.pair_entries[r];
  slice(share.pair_gid_i, e0, en), slice(share.pair_gid_j, e0, en), slice(share.pair_sub, e0, en);
  slice(share.pair_memory.spring, e0, en), slice(share.pair_memory.normal_prev, e0, en);
  slice(share.pair_memory.rolling, e0, en);
  const std::uint64_t w0 = start(l.wall_entries), wn = l.wall_entries[r];
  slice(share.wall_gid, w0, wn), slice(share.wall_index, w0, wn), slice(share.wall_entry_force, w0, wn);
  slice(share.wall_sub, w0, wn), slice(share.wall_memory.spring, w0, wn);
  slice(share.wall_memory.normal_prev, w0, wn), slice(share.wall_memory.rolling, w0, wn);
  share.ranks = 1;
  share.layout = {};
}

}  // namespace

bool WorldState::fits_ranks(std::uint64_t n) const {
  std::uint64_t grid = 1;
  for (const std::vector<double>& cut : layout.cut) grid *= std::max<std::size_t>(2, cut.size()) - 1;
  return n == ranks && n > 1 && grid == n && layout.particles.size() == n && layout.pair_entries.size() == n &&
         layout.wall_entries.size() == n;
}

void World::restore_state(WorldState s, const Communicator* ranks) {
  const std::size_t n = s.particles.owned;
  check_particles(s.particles, table_.species(), shapes_.size(), s.next_gid);
  require(s.position_at_build.size() == n, "positions of the last neighbour-list build missing");
  require(s.wall_force.size() == s.walls.size(), "wall forces do not match the walls");
  for (const Wall& w : s.walls)
    require(w.material >= 0 && w.material < table_.wall_materials(), "wall material not in the scenario");
  require(s.skin > 0, "neighbour-list skin must be positive");
  require(!distributed(), "a distributed world is restored before it is spread over the ranks");
  // Every rank restores the state it was given, whole or its share: none waits for rank 0's.
  settings_.particles_on_first_rank = false;
  if (ranks && s.fits_ranks(static_cast<std::uint64_t>(ranks->size()))) {
    const WorldState::RankLayout& l = s.layout;
    spread_.ranks = RankGrid::with_cuts(*ranks, settings_.domain, l.cut, l.min_width, l.axis);
    for (SlabDecomposition& axis : spread_.ranks.axes) axis.rebalance = false;  // the replayed build keeps its cuts
    const bool rebalance = l.rebalance;  // the share forgets the layout
    keep_share_of_rank(s, ranks->rank());
    replay_last_build(s);
    for (const int a : spread_.ranks.stage_axes()) spread_.ranks.axes[a].rebalance = rebalance;
    return;
  }
  require(s.share_of_rank < 0, "one rank's share of a state restored on another number of ranks");
  if (s.ranks > 1) {
    restore_by_global_ids(s);
    return;
  }
  replay_last_build(s);
}

void World::replay_last_build(const WorldState& s) {
  // Same positions, same order, same constants (and in a distributed world the same cuts and
  // the same neighbours' particles) give the same lists.
  take_state_without_lists(s);
  particles_.position = s.position_at_build;
  time_ = s.time_at_build;
  rebuild();
  require(std::equal(s.particles.gid.begin(), s.particles.gid.end(), particles_.gid.begin()) &&
              std::equal(s.position_at_build.begin(), s.position_at_build.end(), particles_.position.begin()),
          "particles are not in the order of their last neighbour-list build");

  std::copy(s.particles.position.begin(), s.particles.position.end(), particles_.position.begin());
  lists_.ghosts.update_positions(particles_);
  lists_.ghosts.update_velocities(particles_);
  if (distributed()) spread_.halo.forward(particles_);
  time_ = s.time;
  rebuilds_ = s.rebuilds;
  wall_force_ = s.wall_force;

  const std::vector<std::uint32_t>& gid = particles_.gid;
  require(lists_.pairs.entries() == s.pair_gid_i.size() && s.pair_gid_j.size() == s.pair_gid_i.size(),
          "the rebuilt neighbour list has " + std::to_string(lists_.pairs.entries()) + " entries, the stored one " +
              std::to_string(s.pair_gid_i.size()));
  for (std::size_t i = 0; i < lists_.pairs.rows(); ++i)
    for (std::uint32_t e = lists_.pairs.row_begin(i); e < lists_.pairs.row_end(i); ++e)
      require(gid[i] == s.pair_gid_i[e] && gid[lists_.pairs.neighbor(e)] == s.pair_gid_j[e],
              "the rebuilt neighbour list differs from the stored one at entry " + std::to_string(e));
  check_memory_size(s.pair_memory, lists_.pairs.memory, "particle");
  lists_.pairs.memory = s.pair_memory;
  lists_.pairs.remark_memories();
  require(s.pair_sub.size() == shaped_.pair_points.entries(), "contact points of rigid bodies do not match the neighbour list");
  if (has_composites()) shaped_.pair_points.assign(lists_.pairs, s.pair_sub);

  require(lists_.walls.entries() == s.wall_gid.size() && s.wall_index.size() == s.wall_gid.size() &&
              s.wall_entry_force.size() == s.wall_gid.size(),
          "the rebuilt wall-contact list has " + std::to_string(lists_.walls.entries()) + " entries, the stored one " +
              std::to_string(s.wall_gid.size()));
  for (std::size_t i = 0; i < lists_.walls.rows(); ++i)
    for (std::uint32_t e = lists_.walls.row_begin(i); e < lists_.walls.row_end(i); ++e)
      require(gid[i] == s.wall_gid[e] && lists_.walls.wall(e) == s.wall_index[e],
              "the rebuilt wall-contact list differs from the stored one at entry " + std::to_string(e));
  check_memory_size(s.wall_memory, lists_.walls.memory, "wall");
  lists_.walls.memory = s.wall_memory;
  lists_.walls.force_on_wall = s.wall_entry_force;
  require(s.wall_sub.size() == shaped_.wall_points.entries(), "wall contact points of rigid bodies do not match the wall list");
  if (has_composites()) shaped_.wall_points.assign(lists_.walls, s.wall_sub);
  ready_ = true;
}

void World::take_state_without_lists(const WorldState& s) {
  particles_ = s.particles;
  next_gid_ = s.next_gid;
  steps_ = s.steps;
  settings_.gravity = s.gravity;
  settings_.tangential_model = s.tangential_model;
  walls_ = s.walls;
  lists_.skin = s.skin;
  lists_.pairs = PairList{};
  lists_.walls = WallContactList{};
  shaped_.pair_points.clear();
  shaped_.wall_points.clear();
  lists_.gid_at_build.clear();
}

void World::restore_by_global_ids(const WorldState& s) {
  take_state_without_lists(s);
  time_ = s.time;
  wall_force_ = s.wall_force;
  rebuild();  // owned forces stay those of the end of the last step
  rebuilds_ = s.rebuilds;

  // The stored entries as carried memories, keyed by their row's global id.
  const MemoryLayout layout = memory_layout();
  const std::size_t n = s.pair_gid_i.size();
  const auto fits = [n](const std::vector<Vec3>& stored, bool kept) { return n == 0 || (stored.size() == n) == kept; };
  require(s.pair_gid_j.size() == n && fits(s.pair_memory.spring, layout.spring) &&
              fits(s.pair_memory.normal_prev, layout.normal_prev) && fits(s.pair_memory.rolling, layout.rolling),
          "particle contact memory does not fit the scenario's contact model");
  std::vector<CarriedRecord> records(n);
  const auto at = [](const std::vector<Vec3>& v, std::size_t e) { return v.empty() ? Vec3{} : v[e]; };
  for (std::size_t e = 0; e < n; ++e) {
    require(s.pair_gid_i[e] < next_gid_ && s.pair_gid_j[e] < next_gid_, "contact of an unknown particle");
    records[e] = {s.pair_gid_i[e], s.pair_gid_j[e], at(s.pair_memory.spring, e), at(s.pair_memory.normal_prev, e),
                  at(s.pair_memory.rolling, e)};
  }
  // Shaped bodies' contact points, one list per stored entry, go with their records.
  const bool shaped = has_composites();
  require(!shaped || (s.pair_sub.size() == n && s.wall_sub.size() == s.wall_gid.size()),
          "contact points of the rigid bodies missing");
  std::vector<SubContactList> pair_points = shaped ? s.pair_sub : std::vector<SubContactList>{};
  CarriedContacts carried;
  group_records(records, layout, carried, shaped ? &pair_points : nullptr);
  std::vector<std::int64_t> origin;
  lists_.pairs.restore_memory(carried, particles_.gid, shaped ? &origin : nullptr);
  if (shaped) shaped_.pair_points = SubContactStore::from_lists(lists_.pairs, origin, carried.points);

  std::vector<WallMemoryRecord> walls;
  require(s.wall_index.size() == s.wall_gid.size(), "wall contacts damaged");
  for (std::size_t e = 0; e < s.wall_gid.size(); ++e)
    walls.push_back({s.wall_gid[e], s.wall_index[e], at(s.wall_memory.spring, e), at(s.wall_memory.normal_prev, e),
                     at(s.wall_memory.rolling, e)});
  lists_.walls.restore_memory(walls, particles_.gid, shaped ? &origin : nullptr);
  if (shaped) shaped_.wall_points = SubContactStore::from_lists(lists_.walls, origin, s.wall_sub);
  ready_ = true;
}

}  // namespace talus
