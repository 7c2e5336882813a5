#pragma once
// A linked-cell grid with cells at least one interaction range wide. Along periodic axes the
// grid tiles the box exactly and has one extra layer on each side for ghost images, whose
// cell is their owner's cell shifted by a whole box (never re-binned from a rounded position).
#include <array>
#include <cstdint>
#include <vector>

#include "talus/math/vec3.h"
#include "talus/world/domain.h"

namespace talus {

using CellCoord = std::array<std::int32_t, 3>;

class CellGrid {
 public:
  // Sets up cells no narrower than `range` over the owned positions [0, owned). The slab axis
  // is the most even one (below) unless `slab_axis` names it.
  void setup(const Domain& domain, const std::vector<Vec3>& position, std::size_t owned, double range,
             int slab_axis = -1);

  CellCoord coord_of(const Vec3& x) const;  ///< cell of an owned particle (clamped into the grid)
  int cells(int axis) const { return count_[axis]; }
  double origin(int axis) const { return origin_[axis]; }  ///< m, where cell 0 starts
  double width(int axis) const { return width_[axis]; }    ///< m, of a cell
  int slab_axis() const { return slab_axis_; }  ///< the axis whose cell layers hold the particles most evenly
  // Linear index of a cell with the slab axis slowest, over the extended range [first, last].
  std::int64_t linear(const CellCoord& c) const {
    return (c[0] - first_[0]) * stride_[0] + (c[1] - first_[1]) * stride_[1] + (c[2] - first_[2]) * stride_[2];
  }
  std::int64_t linear_size() const;
  std::int64_t stride(int axis) const { return stride_[axis]; }  ///< how far linear() moves for one cell along axis
  int first(int axis) const { return first_[axis]; }
  int last(int axis) const { return last_[axis]; }

  // Fills the cell lists from per-particle cells (owned and ghost).
  void bin(const std::vector<CellCoord>& cell_of);
  // Particles of one cell, in index order.
  const std::uint32_t* begin(std::int64_t cell) const { return items_.data() + start_[cell]; }
  const std::uint32_t* end(std::int64_t cell) const { return items_.data() + start_[cell + 1]; }

 private:
  int most_even_axis(const std::vector<Vec3>& position, std::size_t owned) const;

  Vec3 origin_;
  Vec3 width_;
  int count_[3] = {1, 1, 1};
  int first_[3] = {0, 0, 0}, last_[3] = {0, 0, 0};  ///< extended index range (ghost layers included)
  int slab_axis_ = 0;
  std::int64_t stride_[3] = {1, 1, 1};  ///< linear() steps: 1 along the fastest axis, the slab axis slowest
  std::vector<std::uint32_t> start_;  ///< first item of each cell (32 bits: half the memory)
  std::vector<std::uint32_t> items_;
};

}  // namespace talus
