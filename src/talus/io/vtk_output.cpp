#include "talus/io/vtk_output.h"

#include <algorithm>
#include <cstdio>

#include "talus/io/atomic_file.h"
#include "talus/io/vtk_contacts.h"
#include "talus/io/vtk_particles.h"
#include "talus/io/vtk_shape_mesh.h"
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
  // A table of spheres alone (the world's shape 0 has no parts) would give frames with no cells.
  const bool any_surface = std::any_of(shapes_.begin(), shapes_.end(), [](const CompositeShape& s) {
    return !s.parts.empty() && !is_plain_sphere(s);
  });
  if (any_surface) shapes_series_.emplace(directory_ / "shapes.pvd");
}

std::filesystem::path VtkOutput::frame_file(const char* stem, std::size_t frame, const char* extension) const {
  char name[64];
  std::snprintf(name, sizeof name, "%s_%06zu.%s", stem, frame, extension);
  return name;
}

std::filesystem::path VtkOutput::piece_file(const char* stem, int rank) const {
  char name[80];
  std::snprintf(name, sizeof name, "%s_%06zu_%d.vtu", stem, frames_, rank);
  return name;
}

void VtkOutput::resume(const std::vector<double>& times) {
  auto earlier = [&](const char* stem) {
    std::vector<PvdSeries::Entry> entries;
    for (std::size_t k = 0; k < times.size(); ++k)
      for (const char* extension : {"vtu", "pvtu"})  // whole frames, or frames in pieces
        if (std::filesystem::exists(directory_ / frame_file(stem, k, extension)))
          entries.push_back({times[k], frame_file(stem, k, extension).string()});
    return entries;
  };
  // A restart may write into a new results folder, with no earlier frames in it.
  std::filesystem::create_directories(directory_);
  particles_.add_all(earlier("particles"));
  if (shapes_series_) shapes_series_->add_all(earlier("shapes"));
  contacts_.add_all(earlier("contacts"));
  walls_.add_all(earlier("walls"));
  frames_ = times.size();
}

void VtkOutput::write_frame(const Snapshot& snapshot, const std::vector<Wall>& walls) {
  std::filesystem::create_directories(directory_);
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

void VtkOutput::write_frame_piece(const Snapshot& piece, std::size_t owned, const std::vector<Wall>& walls, int rank,
                                  int ranks, const std::function<void()>& all_written) {
  std::filesystem::create_directories(directory_);
  struct Series {
    const char* stem;
    PvdSeries* series;
    VtuGrid grid;
  };
  std::vector<Series> parts;
  parts.push_back({"particles", &particles_, particles_grid(piece, owned)});
  if (shapes_series_) parts.push_back({"shapes", &*shapes_series_, shapes_grid(piece, owned, shapes_, resolution_)});
  parts.push_back({"contacts", &contacts_, contacts_grid(piece)});
  for (const Series& p : parts) atomic_write(directory_ / piece_file(p.stem, rank), p.grid.serialize());
  all_written();
  if (rank == 0) {
    const double t = piece.time;
    for (const Series& p : parts) {
      std::vector<std::string> pieces;
      for (int r = 0; r < ranks; ++r) pieces.push_back(piece_file(p.stem, r).string());
      atomic_write(directory_ / frame_file(p.stem, frames_, "pvtu"), p.grid.serialize_index(pieces));
      p.series->add(t, frame_file(p.stem, frames_, "pvtu"));
    }
    write_walls_vtu(directory_ / frame_file("walls"), walls, t, Aabb{piece.domain_min, piece.domain_max});
    walls_.add(t, frame_file("walls"));
  }
  ++frames_;
}

}  // namespace talus::io
