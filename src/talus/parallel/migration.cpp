#include "talus/parallel/migration.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

namespace talus {

namespace {
constexpr int kMigrateTag = 160;  // past the halo's (halo_exchange.cpp)
constexpr int kScatterTag = 190;  // past the migration's

struct ParticleRow {
  Vec3 position, velocity, angular_velocity, force, torque;
  Quat orientation;
  double radius, inv_mass, mass;
  Vec3 inv_inertia;
  std::int32_t species, shape;
  std::uint32_t gid;
};

ParticleRow row_of(const ParticleStore& p, std::size_t i) {
  return {p.position[i], p.velocity[i], p.angular_velocity[i], p.force[i], p.torque[i], p.orientation[i],
          p.radius[i],   p.inv_mass[i], p.mass[i],             p.inv_inertia[i], p.species[i], p.shape[i], p.gid[i]};
}

void put_row(ParticleStore& p, std::size_t i, const ParticleRow& r) {
  p.position[i] = r.position;
  p.velocity[i] = r.velocity;
  p.angular_velocity[i] = r.angular_velocity;
  p.force[i] = r.force;
  p.torque[i] = r.torque;
  p.orientation[i] = r.orientation;
  p.radius[i] = r.radius;
  p.inv_mass[i] = r.inv_mass;
  p.mass[i] = r.mass;
  p.inv_inertia[i] = r.inv_inertia;
  p.species[i] = r.species;
  p.shape[i] = r.shape;
  p.gid[i] = r.gid;
}

void put_points(ByteWriter& w, const std::vector<SubContactList>& lists) {
  w.put(static_cast<std::uint64_t>(lists.size()));
  for (const SubContactList& l : lists) {
    w.put(static_cast<std::uint64_t>(l.size()));
    for (const SubContact& s : l) w.put(s);
  }
}

void get_points(ByteReader& r, std::vector<SubContactList>& lists) {
  lists.resize(r.get<std::uint64_t>());
  for (SubContactList& l : lists) {
    l.resize(r.get<std::uint64_t>());
    for (SubContact& s : l) s = r.get<SubContact>();
  }
}

// What goes to one neighbour: the particles entering its slab, then the records (with the
// contact points of shaped bodies: one list per record, or none for spheres).
struct Parcel {
  std::vector<ParticleRow> particles;
  std::vector<CarriedRecord> records;
  std::vector<SubContactList> record_points;
  std::vector<WallMemoryRecord> wall_records;
  std::vector<SubContactList> wall_points;
  std::vector<std::byte> bytes() const {
    std::vector<std::byte> out;
    ByteWriter w(out);
    w.put(static_cast<std::uint64_t>(particles.size()));
    for (const ParticleRow& r : particles) w.put(r);
    w.put(static_cast<std::uint64_t>(records.size()));
    for (const CarriedRecord& r : records) w.put(r);
    put_points(w, record_points);
    w.put(static_cast<std::uint64_t>(wall_records.size()));
    for (const WallMemoryRecord& r : wall_records) w.put(r);
    put_points(w, wall_points);
    return out;
  }
  static Parcel from(const std::vector<std::byte>& in) {
    Parcel p;
    if (in.empty()) return p;
    ByteReader r(in);
    p.particles.resize(r.get<std::uint64_t>());
    for (ParticleRow& row : p.particles) row = r.get<ParticleRow>();
    p.records.resize(r.get<std::uint64_t>());
    for (CarriedRecord& rec : p.records) rec = r.get<CarriedRecord>();
    get_points(r, p.record_points);
    p.wall_records.resize(r.get<std::uint64_t>());
    for (WallMemoryRecord& rec : p.wall_records) rec = r.get<WallMemoryRecord>();
    get_points(r, p.wall_points);
    return p;
  }
};
}  // namespace

MigrationCount migrate(ParticleStore& p, const RankGrid& ranks, CarriedContacts& carried,
                       std::vector<WallMemoryRecord>& wall_memories, const MemoryLayout& layout,
                       MigrationScratch& scratch, std::vector<SubContactList>* wall_points) {
  const bool with_points = wall_points != nullptr;  // shaped bodies
  GidIndex& owned = scratch.owned;  // 1 for the particles this rank holds now, 0 for those gone
  owned.reset(p.owned + p.owned / 4);
  for (std::size_t i = 0; i < p.owned; ++i) owned.put(p.gid[i], 1);
  const auto holds = [&owned](std::uint32_t gid) { return owned.find(gid) == 1; };
  std::vector<CarriedRecord>& records = scratch.records;
  std::vector<SubContactList>& record_points = scratch.record_points;
  records.clear();
  record_points.clear();
  records.reserve(carried.other.size() + carried.other.size() / 8);
  for (std::size_t g = 0; g < carried.groups(); ++g)
    for (std::uint32_t k = carried.start[g]; k < carried.start[g + 1]; ++k) {
      records.push_back(carried_record(carried, carried.key[g], k));
      if (with_points) record_points.push_back(std::move(carried.points[k]));
    }

  MigrationCount count;
  GidIndex& destination = scratch.destination;  // the slab each leaving particle goes to
  int tag = kMigrateTag;
  for (const int axis : ranks.stage_axes()) {
    const SlabDecomposition& slabs = ranks.axes[axis];
    const int me = slabs.index, lower = slabs.lower(), upper = slabs.upper();
    const int lower_rank = ranks.neighbour(axis, -1), upper_rank = ranks.neighbour(axis, +1);
    // Parcels to the neighbours below [0] and above [1]; one parcel if they are the same rank.
    Parcel parcel[2];
    const auto parcel_for = [&](int slab) -> Parcel& { return slab == lower ? parcel[0] : parcel[1]; };
    std::vector<std::uint32_t>& order = scratch.order;
    std::vector<std::uint32_t>& leaving = scratch.leaving;
    order.clear();
    leaving.clear();
    destination.reset(0);
    for (std::size_t i = 0; i < p.owned; ++i) {
      const int owner = slabs.owner_of(p.position[i][axis]);
      if (owner == me) {
        order.push_back(static_cast<std::uint32_t>(i));
        continue;
      }
      if (owner != lower && owner != upper)
        throw std::runtime_error("particle " + std::to_string(p.gid[i]) + " moved from slab " + std::to_string(me) +
                                 " to slab " + std::to_string(owner) + " along axis " + std::to_string(axis) +
                                 ", past a neighbour, between two rebuilds");
      parcel_for(owner).particles.push_back(row_of(p, i));
      leaving.push_back(static_cast<std::uint32_t>(i));
      destination.put(p.gid[i], owner);
      owned.put(p.gid[i], 0);
    }
    std::vector<WallMemoryRecord> staying;
    std::vector<SubContactList> staying_points;
    for (std::size_t n = 0; n < wall_memories.size(); ++n) {
      const WallMemoryRecord& r = wall_memories[n];
      const int to = destination.find(r.gid);
      const bool stays = to == GidIndex::kAbsent;
      Parcel* out = stays ? nullptr : &parcel_for(to);
      (stays ? staying : out->wall_records).push_back(r);
      if (wall_points) (stays ? staying_points : out->wall_points).push_back(std::move((*wall_points)[n]));
    }
    wall_memories = std::move(staying);
    if (wall_points) *wall_points = std::move(staying_points);

    // Records of pairs this rank does not hold wholly go to the neighbours, who may list them
    // now or pass them on along the next axis (a pair across a corner); all stay here until
    // the last stage has run.
    for (std::size_t k = 0; k < records.size(); ++k) {
      const CarriedRecord& r = records[k];
      if (holds(r.a) && holds(r.b)) continue;
      const auto add = [&](Parcel& to) {
        to.records.push_back(r);
        if (with_points) to.record_points.push_back(record_points[k]);
      };
      if (lower_rank >= 0) add(parcel[0]);
      if (upper_rank >= 0 && upper_rank != lower_rank) add(parcel[1]);
    }

    // Down, then up (each rank sends to one neighbour and receives from the other).
    count.left += leaving.size();
    std::vector<Parcel> arrived;
    const auto swap_with = [&](int to, int from, const Parcel& out, int tag) {
      if (to < 0 && from < 0) return;
      arrived.push_back(Parcel::from(ranks.comm->exchange(out.bytes(), to, from, tag)));
    };
    swap_with(lower_rank, upper_rank, parcel[0], tag);
    if (upper_rank != lower_rank) swap_with(upper_rank, lower_rank, parcel[1], tag + 2);
    tag += 4;

    // Leavers go (the order keeps the others in place), arrivals are appended.
    const std::size_t stay = order.size();
    if (!leaving.empty()) {
      order.insert(order.end(), leaving.begin(), leaving.end());
      p.permute_owned(order);
    }
    std::size_t arriving = 0;
    for (const Parcel& in : arrived) arriving += in.particles.size();
    p.owned = stay;
    p.resize(stay + arriving);
    p.owned = stay + arriving;
    std::size_t i = stay;
    for (const Parcel& in : arrived) {
      for (const ParticleRow& r : in.particles) {
        put_row(p, i++, r);
        owned.put(r.gid, 1);
        ++count.arrived;
      }
      records.insert(records.end(), in.records.begin(), in.records.end());
      record_points.insert(record_points.end(), in.record_points.begin(), in.record_points.end());
      wall_memories.insert(wall_memories.end(), in.wall_records.begin(), in.wall_records.end());
      if (wall_points) wall_points->insert(wall_points->end(), in.wall_points.begin(), in.wall_points.end());
    }
  }

  // Every record keyed by a particle this rank owns (seen from it; memories change sign when
  // seen from the other body), the others dropped; then grouped by key as carry() makes them.
  std::size_t n = 0;
  for (std::size_t k = 0; k < records.size(); ++k) {
    CarriedRecord& r = records[k];
    if (!holds(r.a)) {
      if (!holds(r.b)) continue;
      r = {r.b, r.a, -1.0 * r.spring, -1.0 * r.normal_prev, -1.0 * r.rolling};
      if (with_points) reverse_points(record_points[k]);
    }
    if (with_points && n != k) record_points[n] = std::move(record_points[k]);
    records[n++] = r;
  }
  records.resize(n);
  if (with_points) record_points.resize(n);
  group_records(records, layout, carried, with_points ? &record_points : nullptr);
  return count;
}

std::size_t scatter_from_first_rank(ParticleStore& p, const RankGrid& ranks, const Domain& domain) {
  // Messages of at most this many particles (about 150 MB): MPI counts bytes in an int.
  constexpr std::size_t kRowsPerMessage = std::size_t{1} << 20;
  const Communicator& comm = *ranks.comm;
  if (comm.rank() != 0) {
    if (p.owned != 0) throw std::logic_error("scatter_from_first_rank: a rank other than the first holds particles");
    const std::vector<std::byte> head = comm.exchange({}, -1, 0, kScatterTag);
    const std::uint64_t n = ByteReader(head).get<std::uint64_t>();
    p.resize(n);
    p.owned = n;
    for (std::size_t at = 0; at < n; at += kRowsPerMessage) {
      const std::vector<std::byte> in = comm.exchange({}, -1, 0, kScatterTag);
      ByteReader r(in);
      for (std::size_t i = at; i < std::min<std::size_t>(n, at + kRowsPerMessage); ++i) put_row(p, i, r.get<ParticleRow>());
    }
    return 0;
  }
  std::vector<std::vector<std::uint32_t>> of_rank(static_cast<std::size_t>(comm.size()));
  for (std::size_t i = 0; i < p.owned; ++i) {
    const Vec3 x = domain.wrap(p.position[i]);
    std::array<int, 3> index;
    for (int a = 0; a < 3; ++a) index[a] = ranks.axes[a].owner_of(x[a]);
    of_rank[static_cast<std::size_t>(ranks.rank_at(index))].push_back(static_cast<std::uint32_t>(i));
  }
  std::size_t sent = 0;
  for (int to = 1; to < comm.size(); ++to) {
    const std::vector<std::uint32_t>& rows = of_rank[static_cast<std::size_t>(to)];
    std::vector<std::byte> out;
    ByteWriter(out).put(static_cast<std::uint64_t>(rows.size()));
    comm.exchange(out, to, -1, kScatterTag);
    for (std::size_t at = 0; at < rows.size(); at += kRowsPerMessage) {
      out.clear();
      ByteWriter w(out);
      for (std::size_t k = at; k < std::min(rows.size(), at + kRowsPerMessage); ++k) w.put(row_of(p, rows[k]));
      comm.exchange(out, to, -1, kScatterTag);
    }
    sent += rows.size();
  }
  // Rank 0 keeps its own share, in the order it had them.
  std::vector<std::uint32_t> order = std::move(of_rank[0]);
  const std::size_t mine = order.size();
  for (int to = 1; to < comm.size(); ++to)
    order.insert(order.end(), of_rank[static_cast<std::size_t>(to)].begin(), of_rank[static_cast<std::size_t>(to)].end());
  p.permute_owned(order);
  p.owned = mine;
  p.resize(mine);
  return sent;
}

}  // namespace talus
