#pragma once
// Candidate particle-wall contacts: for each owned particle, the walls within a skin of it,
// with their contact memory. Rebuilt with the pair list.
#include <cstdint>
#include <vector>

#include "talus/body/particles.h"
#include "talus/collide/pair_list.h"
#include "talus/world/wall.h"

namespace talus {

// The memory of one particle-wall contact, keyed by the particle's global id: what a particle
// takes along when it moves to another rank (parallel/migration.h).
struct WallMemoryRecord {
  std::uint32_t gid = 0;
  std::int32_t wall = 0;
  Vec3 spring, normal_prev, rolling;
};

class WallContactList {
 public:
  void build(const ParticleStore& particles, const std::vector<Wall>& walls, double time, double skin,
             const MemoryLayout& layout);
  // `origin`, if given, receives per new entry the old entry it continues (+1; 0 if new).
  void transfer_memory(const WallContactList& old, const std::vector<std::uint32_t>& old_gid,
                       const std::vector<std::uint32_t>& gid, std::vector<std::int64_t>* origin = nullptr);

  // The memories of the entries in contact (of every entry if `every_entry`: shaped bodies keep
  // theirs outside the list), keyed by global id (`gid` of this list's rows); `entries`, if
  // given, receives each record's entry.
  std::vector<WallMemoryRecord> carry(const std::vector<std::uint32_t>& gid, bool every_entry = false,
                                      std::vector<std::uint32_t>* entries = nullptr) const;
  // Hands `records` to the entries of this list built anew; records without an entry are dropped.
  // `origin`, if given, receives per entry the record it took (+1; 0 if none).
  void restore_memory(const std::vector<WallMemoryRecord>& records, const std::vector<std::uint32_t>& gid,
                      std::vector<std::int64_t>* origin = nullptr);

  std::uint32_t row_begin(std::size_t i) const { return row_[i]; }
  std::uint32_t row_end(std::size_t i) const { return row_[i + 1]; }
  std::int32_t wall(std::size_t e) const { return wall_[e]; }
  std::size_t entries() const { return wall_.size(); }
  std::size_t rows() const { return row_.empty() ? 0 : row_.size() - 1; }

  ContactMemory memory;
  std::vector<Vec3> force_on_wall;  ///< N, per entry, filled by the force pass

 private:
  std::vector<std::uint32_t> row_;
  std::vector<std::int32_t> wall_;
};

// Distance from a sphere's centre to a wall along the wall normal, and whether the centre
// projects inside a bounded wall (with `margin` of slack).
bool wall_faces(const Wall& wall, const Vec3& origin, const Vec3& x, double margin);

// Where a sphere touches a wall.
struct SphereWallTouch {
  Vec3 normal;              ///< from the wall towards the sphere's centre
  double overlap = 0;       ///< m
  double inv_distance = 0;  ///< 1/m: 1/|x - c| on a plate's rim, 0 on a face (a face's normal cannot turn)
};
// A plain wall is its plane. A bounded wall is a one-sided plate: a sphere in front of it meets the
// rectangle's closest point c, on the face, an edge or a corner, so a sphere coming round an edge
// is touched from zero depth on, not caught at once when its centre comes over the face.
bool sphere_touches_wall(const Wall& wall, const Vec3& origin, const Vec3& x, double radius, SphereWallTouch& touch);

}  // namespace talus
