#pragma once
// Half neighbour list with a skin (each pair once, Newton's third law), in CSR rows over the
// owned particles, with the contact memory stored beside each entry.
//
// Pair orientation makes the force loop race-free and deterministic on any number of threads:
// owned particles are sorted by slab (a layer of cells along the grid's longest axis), and a
// pair (i, j) is stored with slab(j) >= slab(i) (ties broken by global id). A slab then writes
// only to itself and the next slab, so all even slabs can run concurrently, then all odd ones,
// and every particle receives its contributions in the same order whatever the thread count.
#include <cstdint>
#include <vector>

#include "talus/body/gid_index.h"
#include "talus/body/particles.h"
#include "talus/collide/cell_grid.h"
#include "talus/math/vec3.h"
#include "talus/world/sub_contacts.h"

namespace talus {

// Which per-contact memories the contact law needs.
struct MemoryLayout {
  bool spring = false;       ///< tangential displacement delta_t
  bool normal_prev = false;  ///< previous normal, to turn the memories with the tangent plane
  bool rolling = false;      ///< rolling torque spring M_k
};

// Per-entry contact memory, as parallel arrays (an array is empty when its memory is off).
struct ContactMemory {
  std::vector<Vec3> spring, normal_prev, rolling;
  void resize(std::size_t n, const MemoryLayout& layout);  ///< n zeroed entries
  // n entries, those already held left as they are: for a caller that writes every entry.
  void resize_for_overwrite(std::size_t n, const MemoryLayout& layout);
  bool active(std::size_t e) const;  ///< true if entry e remembers a contact
  void clear(std::size_t e);
  // Copies entry `from` of `source` into entry `to`; `reversed` when the pair's order flipped.
  void copy_from(const ContactMemory& source, std::size_t from, std::size_t to, bool reversed);
};

// The memories of a list's entries keyed by the global ids of their pair, compact (only the
// entries kept), so that a list can be rebuilt after its old form has been freed. Records are
// grouped by their key a, the groups in no particular order, the records of one group in the
// order they were carried; `group_of` finds a key's group.
struct CarriedContacts {
  std::vector<std::uint32_t> key;    ///< global id a of each group
  std::vector<std::uint32_t> start;  ///< per group: its first record, then the record count
  GidIndex group_of;                 ///< global id a -> its group
  std::vector<std::uint32_t> other;  ///< global id b of each record
  std::vector<std::uint32_t> entry;  ///< the record's entry in the list it came from
  ContactMemory memory;              ///< the record's memory, as seen from a
  // Shaped bodies between ranks: each record's contact points, seen from a (then `entry` holds
  // each record's own index, the origin of the SubContactStore of the new list).
  std::vector<SubContactList> points;
  std::size_t groups() const { return key.size(); }
  std::size_t bytes() const;  ///< memory held
};

// One carried memory as plain data: the pair's global ids (a, b) and its memory seen from a.
// What crosses between ranks and what a checkpoint gathered from ranks holds.
struct CarriedRecord {
  std::uint32_t a = 0, b = 0;
  Vec3 spring, normal_prev, rolling;
};

// Record k of `carried`, whose key is global id a.
CarriedRecord carried_record(const CarriedContacts& carried, std::uint32_t a, std::size_t k);
// `records` grouped by their key a into `carried`, as PairList::carry makes them (no entries of
// origin): groups in the order their keys first appear, each group's records in their order.
// Memories the layout does not keep are dropped. `points`, if given, are the records' contact
// points (one list per record), grouped with them.
void group_records(const std::vector<CarriedRecord>& records, const MemoryLayout& layout, CarriedContacts& carried,
                   std::vector<SubContactList>* points = nullptr);

class PairList {
 public:
  // Builds the list over owned particles (sorted by slab) and ghosts; pairs whose bounding
  // spheres are within `skin` of touching. Pairs of two fixed particles are left out.
  void build(const ParticleStore& particles, const std::vector<CellCoord>& cell_of, const CellGrid& grid,
             double skin, const MemoryLayout& layout);
  // Carries the memory of every pair still listed over from `old` (keyed by global ids).
  // `origin`, if given, receives per new entry the old entry it continues (+1, negated when
  // the pair's order flipped; 0 for a new pair), for memories kept outside the list.
  void transfer_memory(const PairList& old, const std::vector<std::uint32_t>& old_gid,
                       const std::vector<std::uint32_t>& gid, std::vector<std::int64_t>* origin = nullptr);
  // The same in two halves, so that the list can be rebuilt in place: `carry` writes into
  // `carried` (reusing its buffers) the entries that remember a contact (every entry if
  // `every_entry`), keyed by the global ids `gid` of this list's particles; `restore_memory`
  // hands them to this list built anew (`origin` as for transfer_memory).
  void carry(const std::vector<std::uint32_t>& gid, bool every_entry, CarriedContacts& carried) const;
  // Empties the list; its buffers keep their memory for the next build (the memories also
  // their length, which build() resets).
  void clear();
  void restore_memory(const CarriedContacts& carried, const std::vector<std::uint32_t>& gid,
                      std::vector<std::int64_t>* origin = nullptr);

  std::size_t rows() const { return row_.empty() ? 0 : row_.size() - 1; }
  std::uint32_t row_begin(std::size_t i) const { return row_[i]; }
  std::uint32_t row_end(std::size_t i) const { return row_[i + 1]; }
  std::uint32_t neighbor(std::size_t e) const { return neighbor_[e]; }
  std::size_t entries() const { return neighbor_.size(); }
  std::size_t slabs() const { return slab_start_.empty() ? 0 : slab_start_.size() - 1; }
  std::uint32_t slab_begin(std::size_t s) const { return slab_start_[s]; }
  std::uint32_t slab_end(std::size_t s) const { return slab_start_[s + 1]; }
  // Runs of consecutive slabs of about equal work (entries and rows), as slab indices
  // [chunk[c], chunk[c + 1]): the units of the parallel force pass. They depend on the list
  // only, never on the number of threads.
  const std::vector<std::uint32_t>& slab_chunks() const { return chunk_; }
  // Largest j - i over the entries (i, j) with j an owned particle after i: a pass over the
  // rows in order first meets particle i + forward_reach() in row i.
  std::uint32_t forward_reach() const { return forward_reach_; }
  const std::uint32_t* neighbors() const { return neighbor_.data(); }
  const std::uint32_t* row_offsets() const { return row_.data(); }
  // Per entry, 1 if its memory may be non-zero: the sphere pair loop reads this byte, not the
  // memories, to find the contacts that just ended (most entries are apart and stay so).
  // Derived from `memory`: call remark_memories() after writing `memory` from outside.
  std::uint8_t* remembered() { return remembered_.data(); }
  void remark_memories();
  std::size_t bytes() const;

  ContactMemory memory;

 private:
  void split_slabs();

  std::vector<std::uint32_t> row_;
  std::vector<std::uint32_t> neighbor_;
  std::vector<std::uint8_t> remembered_;
  std::vector<std::uint32_t> slab_start_;  ///< first owned particle of each slab
  std::vector<std::uint32_t> chunk_;       ///< first slab of each chunk, then the slab count
  std::uint32_t forward_reach_ = 0;
  GidIndex row_of_gid_;  ///< restore_memory's map, kept between rebuilds
};

}  // namespace talus
