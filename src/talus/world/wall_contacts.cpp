#include "talus/world/wall_contacts.h"

#include <algorithm>
#include <cmath>

namespace talus {

bool wall_faces(const Wall& w, const Vec3& origin, const Vec3& x, double margin) {
  if (!w.bounded) return true;
  const Vec3 q = x - origin;
  return std::abs(dot(q, w.axis_u)) <= w.half_extent_u + margin &&
         std::abs(dot(q, w.axis_v)) <= w.half_extent_v + margin;
}

bool sphere_touches_wall(const Wall& w, const Vec3& origin, const Vec3& x, double radius, SphereWallTouch& touch) {
  const Vec3 q = x - origin;
  const double gap = dot(q, w.normal);
  if (gap >= radius || (w.bounded && gap < 0)) return false;
  if (w.bounded) {
    const double u = dot(q, w.axis_u), v = dot(q, w.axis_v);
    const double beyond_u = u - std::clamp(u, -w.half_extent_u, w.half_extent_u);
    const double beyond_v = v - std::clamp(v, -w.half_extent_v, w.half_extent_v);
    if (beyond_u != 0 || beyond_v != 0) {  // off the face: the rim
      const Vec3 d = w.axis_u * beyond_u + w.axis_v * beyond_v + w.normal * gap;
      const double distance = std::sqrt(dot(d, d));
      if (distance >= radius || distance == 0) return false;
      touch = {d / distance, radius - distance, 1 / distance};
      return true;
    }
  }
  touch = {w.normal, radius - gap, 0};
  return true;
}

void WallContactList::build(const ParticleStore& p, const std::vector<Wall>& walls, double time, double skin,
                            const MemoryLayout& layout) {
  row_.assign(p.owned + 1, 0);
  wall_.clear();
  for (std::size_t i = 0; i < p.owned; ++i) {
    for (std::size_t w = 0; w < walls.size(); ++w) {
      const Wall& wall = walls[w];
      if (!wall.active(time)) continue;
      const Vec3 origin = wall.origin_at(time);
      const double d = dot(p.position[i] - origin, wall.normal);
      if (d < p.radius[i] + skin && (!wall.bounded || d > -skin) &&
          (wall.moves() || wall_faces(wall, origin, p.position[i], p.radius[i] + skin)))
        wall_.push_back(static_cast<std::int32_t>(w));
    }
    row_[i + 1] = static_cast<std::uint32_t>(wall_.size());
  }
  memory.resize(wall_.size(), layout);
  force_on_wall.assign(wall_.size(), Vec3{});
}

void WallContactList::transfer_memory(const WallContactList& old, const std::vector<std::uint32_t>& old_gid,
                                      const std::vector<std::uint32_t>& gid, std::vector<std::int64_t>* origin) {
  if (origin) origin->assign(entries(), 0);
  if (old.entries() == 0) return;
  GidIndex old_row_of;
  old_row_of.index_positions(std::span<const std::uint32_t>(old_gid.data(), old.rows()));
  for (std::size_t i = 0; i < rows(); ++i) {
    const std::int32_t r = old_row_of.find(gid[i]);
    if (r < 0) continue;
    for (std::uint32_t e = row_[i]; e < row_[i + 1]; ++e)
      for (std::uint32_t f = old.row_begin(r); f < old.row_end(r); ++f) {
        if (old.wall(f) != wall_[e]) continue;
        if (old.memory.active(f)) memory.copy_from(old.memory, f, e, false);
        if (origin) (*origin)[e] = f + 1;
      }
  }
}

std::vector<WallMemoryRecord> WallContactList::carry(const std::vector<std::uint32_t>& gid, bool every_entry,
                                                     std::vector<std::uint32_t>* entries) const {
  std::vector<WallMemoryRecord> records;
  if (entries) entries->clear();
  const auto at = [](const std::vector<Vec3>& v, std::size_t e) { return v.empty() ? Vec3{} : v[e]; };
  for (std::size_t i = 0; i < rows(); ++i)
    for (std::uint32_t e = row_[i]; e < row_[i + 1]; ++e)
      if (every_entry || memory.active(e)) {
        records.push_back({gid[i], wall_[e], at(memory.spring, e), at(memory.normal_prev, e), at(memory.rolling, e)});
        if (entries) entries->push_back(e);
      }
  return records;
}

void WallContactList::restore_memory(const std::vector<WallMemoryRecord>& records,
                                     const std::vector<std::uint32_t>& gid, std::vector<std::int64_t>* origin) {
  if (origin) origin->assign(entries(), 0);
  if (records.empty()) return;
  GidIndex row_of;
  row_of.index_positions(std::span<const std::uint32_t>(gid.data(), rows()));
  for (std::size_t k = 0; k < records.size(); ++k) {
    const WallMemoryRecord& r = records[k];
    const std::int32_t i = row_of.find(r.gid);
    if (i < 0) continue;
    for (std::uint32_t e = row_[i]; e < row_[i + 1]; ++e) {
      if (wall_[e] != r.wall) continue;
      if (origin) (*origin)[e] = static_cast<std::int64_t>(k) + 1;
      if (!memory.spring.empty()) memory.spring[e] = r.spring;
      if (!memory.normal_prev.empty()) memory.normal_prev[e] = r.normal_prev;
      if (!memory.rolling.empty()) memory.rolling[e] = r.rolling;
    }
  }
}

}  // namespace talus
