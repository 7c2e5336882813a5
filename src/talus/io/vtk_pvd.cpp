#include "talus/io/vtk_pvd.h"

#include "talus/io/atomic_file.h"
#include "talus/io/number_format.h"
#include "talus/io/vtk_xml.h"

namespace talus::io {

PvdSeries::PvdSeries(std::filesystem::path pvd_path) : path_(std::move(pvd_path)) {}

void PvdSeries::add(double time, const std::filesystem::path& file) {
  std::filesystem::path relative = file;
  if (file.is_absolute()) {
    const std::filesystem::path dir = std::filesystem::absolute(path_).parent_path();
    relative = file.lexically_relative(dir);
    if (relative.empty()) relative = file;  // another root: keep the absolute name
  }
  entries_.push_back({time, relative.generic_string()});
  atomic_write(path_, xml());
}

void PvdSeries::add_all(const std::vector<Entry>& entries) {
  entries_.insert(entries_.end(), entries.begin(), entries.end());
  atomic_write(path_, xml());
}

std::string PvdSeries::xml() const {
  std::string out =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"1.0\">\n"
      "  <Collection>\n";
  for (const Entry& e : entries_) {
    out += "    <DataSet timestep=\"";
    append_double(out, e.time);
    out += "\" group=\"\" part=\"0\" file=\"";
    out += xml_escape(e.file);
    out += "\"/>\n";
  }
  out += "  </Collection>\n</VTKFile>\n";
  return out;
}

}  // namespace talus::io
