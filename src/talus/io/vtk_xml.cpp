#include "talus/io/vtk_xml.h"

#include <bit>
#include <cstring>
#include <stdexcept>
#include <type_traits>

namespace talus::io {

namespace {

template <class T>
constexpr const char* vtk_type_name() {
  if constexpr (std::is_same_v<T, double>) return "Float64";
  else if constexpr (std::is_same_v<T, float>) return "Float32";
  else if constexpr (std::is_same_v<T, std::int32_t>) return "Int32";
  else if constexpr (std::is_same_v<T, std::uint32_t>) return "UInt32";
  else if constexpr (std::is_same_v<T, std::int64_t>) return "Int64";
  else if constexpr (std::is_same_v<T, std::uint8_t>) return "UInt8";
  else static_assert(sizeof(T) == 0, "unsupported VTK array element type");
}

template <class T>
std::string raw_bytes(std::span<const T> values) {
  std::string out(values.size_bytes(), '\0');
  if (!values.empty()) std::memcpy(out.data(), values.data(), values.size_bytes());
  return out;
}

// One appended block: UInt64 byte count, then the bytes.
void append_block(std::string& out, std::string_view bytes) {
  const std::uint64_t n = bytes.size();
  out.append(reinterpret_cast<const char*>(&n), sizeof n);
  out.append(bytes);
}

void array_header(std::string& out, const char* type, std::string_view name, int components,
                  std::uint64_t offset) {
  out += "        <DataArray type=\"";
  out += type;
  out += '"';
  if (!name.empty()) {
    out += " Name=\"";
    out += xml_escape(name);
    out += '"';
  }
  if (components != 1) out += " NumberOfComponents=\"" + std::to_string(components) + '"';
  out += " format=\"appended\" offset=\"" + std::to_string(offset) + "\"/>\n";
}

}  // namespace

std::string xml_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

std::int64_t VtuGrid::add_point(const Vec3& p) {
  points_.insert(points_.end(), {p.x, p.y, p.z});
  return static_cast<std::int64_t>(points() - 1);
}

void VtuGrid::add_cell(VtkCellType type, std::span<const std::int64_t> point_ids) {
  for (std::int64_t id : point_ids)
    if (id < 0 || static_cast<std::size_t>(id) >= points())
      throw std::out_of_range("VtuGrid::add_cell: point index " + std::to_string(id) +
                              " of " + std::to_string(points()));
  connectivity_.insert(connectivity_.end(), point_ids.begin(), point_ids.end());
  offsets_.push_back(static_cast<std::int64_t>(connectivity_.size()));
  types_.push_back(static_cast<std::uint8_t>(type));
}

template <class T>
void VtuGrid::add_array(Where where, std::string_view name, int components, std::span<const T> values) {
  if (components < 1) throw std::invalid_argument("VtuGrid::add_array: components < 1");
  arrays_.push_back({where, std::string(name), vtk_type_name<T>(), components, values.size(),
                     raw_bytes(values)});
}

void VtuGrid::add_array(Where where, std::string_view name, std::span<const Vec3> values) {
  std::vector<double> flat;
  flat.reserve(3 * values.size());
  for (const Vec3& v : values) flat.insert(flat.end(), {v.x, v.y, v.z});
  add_array<double>(where, name, 3, flat);
}

template void VtuGrid::add_array<double>(Where, std::string_view, int, std::span<const double>);
template void VtuGrid::add_array<float>(Where, std::string_view, int, std::span<const float>);
template void VtuGrid::add_array<std::int32_t>(Where, std::string_view, int, std::span<const std::int32_t>);
template void VtuGrid::add_array<std::uint32_t>(Where, std::string_view, int, std::span<const std::uint32_t>);
template void VtuGrid::add_array<std::int64_t>(Where, std::string_view, int, std::span<const std::int64_t>);
template void VtuGrid::add_array<std::uint8_t>(Where, std::string_view, int, std::span<const std::uint8_t>);

std::string VtuGrid::serialize() const {
  for (const Array& a : arrays_) {
    const std::size_t tuples = a.where == Where::kPoint ? points() : cells();
    if (a.tuples_times_components != tuples * static_cast<std::size_t>(a.components))
      throw std::logic_error("VtuGrid: array '" + a.name + "' has " +
                             std::to_string(a.tuples_times_components) + " values, expected " +
                             std::to_string(tuples * a.components));
  }
  const char* byte_order = std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";

  std::string xml;
  std::string appended;
  xml += "<?xml version=\"1.0\"?>\n";
  xml += "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"";
  xml += byte_order;
  xml += "\" header_type=\"UInt64\">\n  <UnstructuredGrid>\n";
  xml += "    <Piece NumberOfPoints=\"" + std::to_string(points()) + "\" NumberOfCells=\"" +
         std::to_string(cells()) + "\">\n";
  for (Where where : {Where::kPoint, Where::kCell}) {
    xml += where == Where::kPoint ? "      <PointData>\n" : "      <CellData>\n";
    for (const Array& a : arrays_) {
      if (a.where != where) continue;
      array_header(xml, a.type, a.name, a.components, appended.size());
      append_block(appended, a.bytes);
    }
    xml += where == Where::kPoint ? "      </PointData>\n" : "      </CellData>\n";
  }
  xml += "      <Points>\n";
  array_header(xml, "Float64", "Points", 3, appended.size());
  append_block(appended, raw_bytes(std::span<const double>(points_)));
  xml += "      </Points>\n      <Cells>\n";
  array_header(xml, "Int64", "connectivity", 1, appended.size());
  append_block(appended, raw_bytes(std::span<const std::int64_t>(connectivity_)));
  array_header(xml, "Int64", "offsets", 1, appended.size());
  append_block(appended, raw_bytes(std::span<const std::int64_t>(offsets_)));
  array_header(xml, "UInt8", "types", 1, appended.size());
  append_block(appended, raw_bytes(std::span<const std::uint8_t>(types_)));
  xml += "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n";
  xml += "  <AppendedData encoding=\"raw\">\n   _";
  xml += appended;
  xml += "\n  </AppendedData>\n</VTKFile>\n";
  return xml;
}

std::string VtuGrid::serialize_index(const std::vector<std::string>& pieces) const {
  const char* byte_order = std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";
  std::string xml = "<?xml version=\"1.0\"?>\n<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" byte_order=\"";
  xml += byte_order;
  xml += "\" header_type=\"UInt64\">\n  <PUnstructuredGrid GhostLevel=\"0\">\n";
  auto declare = [&](const char* type, std::string_view name, int components) {
    xml += "      <PDataArray type=\"";
    xml += type;
    xml += '"';
    if (!name.empty()) xml += " Name=\"" + xml_escape(name) + '"';
    if (components != 1) xml += " NumberOfComponents=\"" + std::to_string(components) + '"';
    xml += "/>\n";
  };
  for (Where where : {Where::kPoint, Where::kCell}) {
    xml += where == Where::kPoint ? "    <PPointData>\n" : "    <PCellData>\n";
    for (const Array& a : arrays_)
      if (a.where == where) declare(a.type, a.name, a.components);
    xml += where == Where::kPoint ? "    </PPointData>\n" : "    </PCellData>\n";
  }
  xml += "    <PPoints>\n";
  declare("Float64", "Points", 3);
  xml += "    </PPoints>\n";
  for (const std::string& piece : pieces) xml += "    <Piece Source=\"" + xml_escape(piece) + "\"/>\n";
  xml += "  </PUnstructuredGrid>\n</VTKFile>\n";
  return xml;
}

}  // namespace talus::io
