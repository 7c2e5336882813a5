#include "talus/io/vtk_output.h"

#include <cstdio>

#include "talus/io/vtk_contacts.h"
#include "talus/io/vtk_particles.h"
#include "talus/io/vtk_walls.h"

namespace talus::io {

VtkOutput::VtkOutput(std::filesystem::path directory, std::vector<CompositeShape> shapes,
                     MeshResolution resolution)
    : directory_(std::move(directory)),
      shapes_(std::move(shapes)),
      resolution_(resolution),
      particles_(directory_ / "particles.pvd"),
      contacts_(directory_ / "contacts.pvd"),
      walls_(directory_ / "walls.pvd") {
  std::filesystem::create_directories(directory_);
  if (!shapes_.empty()) shapes_series_.emplace(directory_ / "shapes.pvd");
}

std::filesystem::path VtkOutput::frame_file(const char* stem, std::size_t frame) const {
  char name[64];
  std::snprintf(name, sizeof name, "%s_%06zu.vtu", stem, frame);
  return name;
}

void VtkOutput::resume(const std::vector<double>& times) {
  auto earlier = [&](const char* stem) {
    std::vector<PvdSeries::Entry> entries;
    for (std::size_t k = 0; k < times.size(); ++k)
      if (std::filesystem::exists(directory_ / frame_file(stem, k))) entries.push_back({times[k], frame_file(stem, k).string()});
    return entries;
  };
  particles_.add_all(earlier("particles"));
  if (shapes_series_) shapes_series_->add_all(earlier("shapes"));
  contacts_.add_all(earlier("contacts"));
  walls_.add_all(earlier("walls"));
  frames_ = times.size();
}

void VtkOutput::write_frame(const Snapshot& snapshot, const std::vector<Wall>& walls) {
  const double t = snapshot.time;
  write_particles_vtu(directory_ / frame_file("particles"), snapshot);
  particles_.add(t, frame_file("particles"));
  if (shapes_series_) {
    write_shapes_vtu(directory_ / frame_file("shapes"), snapshot, shapes_, resolution_);
    shapes_series_->add(t, frame_file("shapes"));
  }
  write_contacts_vtu(directory_ / frame_file("contacts"), snapshot);
  contacts_.add(t, frame_file("contacts"));
  write_walls_vtu(directory_ / frame_file("walls"), walls, t, Aabb{snapshot.domain_min, snapshot.domain_max});
  walls_.add(t, frame_file("walls"));
  ++frames_;
}

}  // namespace talus::io
