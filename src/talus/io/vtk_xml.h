#pragma once
// VtuGrid: an in-memory VTK UnstructuredGrid serialized as a VTK XML .vtu file (version 1.0,
// UInt64 block headers, binary data in one raw <AppendedData> block). The ParaView writers
// (vtk_particles.h, vtk_contacts.h, vtk_walls.h) fill one grid each; this file knows nothing
// about particles.
// Format: https://docs.vtk.org/en/latest/design_documents/VTKFileFormats.html (XML formats).
// Cell offsets are stored as VTK's XML reader expects them: the end of each cell's
// connectivity, without a leading zero.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "talus/math/vec3.h"

namespace talus::io {

enum class VtkCellType : std::uint8_t {
  kVertex = 1,
  kLine = 3,
  kTriangle = 5,
  kPolygon = 7,
  kQuad = 9,
};

class VtuGrid {
 public:
  enum class Where { kPoint, kCell };

  // Returns the new point's index.
  std::int64_t add_point(const Vec3& p);
  // Point indices must already exist (std::out_of_range otherwise).
  void add_cell(VtkCellType type, std::span<const std::int64_t> point_ids);
  void add_cell(VtkCellType type, std::initializer_list<std::int64_t> point_ids) {
    add_cell(type, std::span<const std::int64_t>(point_ids.begin(), point_ids.size()));
  }

  // Data arrays: values.size() must be components x (points or cells) when serialized
  // (checked there, std::logic_error). Supported element types: double, float, int32,
  // uint32, int64, uint8.
  template <class T>
  void add_array(Where where, std::string_view name, int components, std::span<const T> values);
  template <class T>
  void add_array(Where where, std::string_view name, int components, const std::vector<T>& values) {
    add_array<T>(where, name, components, std::span<const T>(values));
  }
  void add_array(Where where, std::string_view name, std::span<const Vec3> values);  // 3 components

  std::size_t points() const { return points_.size() / 3; }
  std::size_t cells() const { return types_.size(); }

  // The complete .vtu file.
  std::string serialize() const;
  // A .pvtu file that joins `pieces` (.vtu files, relative to the .pvtu), each with this grid's
  // arrays: the data of one frame written piece by piece, one per rank.
  std::string serialize_index(const std::vector<std::string>& pieces) const;

 private:
  struct Array {
    Where where;
    std::string name;
    const char* type;  ///< VTK type name (Float64, Int32, ...)
    int components;
    std::size_t tuples_times_components;
    std::string bytes;  ///< native byte order
  };

  std::vector<double> points_;  ///< x, y, z per point (m)
  std::vector<std::int64_t> connectivity_;
  std::vector<std::int64_t> offsets_;  ///< end of each cell in connectivity_
  std::vector<std::uint8_t> types_;
  std::vector<Array> arrays_;
};

// Escapes &, <, >, " and ' for an XML attribute value.
std::string xml_escape(std::string_view text);

}  // namespace talus::io
