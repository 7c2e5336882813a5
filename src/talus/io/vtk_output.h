#pragma once
// VtkOutput: everything ParaView needs for a run, one call per frame. In `directory`:
//   particles_NNNNNN.vtu  centres + particle data          (series particles.pvd)
//   shapes_NNNNNN.vtu     surfaces of non-spherical shapes (series shapes.pvd; only when the
//                         shape table has one)
//   contacts_NNNNNN.vtu   contact network                  (series contacts.pvd)
//   walls_NNNNNN.vtu      walls at the frame's time        (series walls.pvd)
// NNNNNN counts frames from 0. A run spread over ranks writes each frame of particles, shapes
// and contacts in pieces, one per rank (stem_NNNNNN_R.vtu, R the rank), joined by
// stem_NNNNNN.pvtu, which the series lists. Each .pvd is rewritten after its frame's files are
// complete, so a reader of the .pvd never meets a missing or partial frame. Open the four .pvd
// files in ParaView.
#include <filesystem>
#include <functional>
#include <optional>
#include <vector>

#include "talus/analysis/snapshot.h"
#include "talus/io/vtk_pvd.h"
#include "talus/io/vtk_shape_mesh.h"
#include "talus/shape/composite_shape.h"
#include "talus/world/wall.h"

namespace talus::io {

class VtkOutput {
 public:
  // `directory` is created with the first frame. `shapes` is the scenario's shape table, indexed by
  // ParticleRecord::shape; with no shape but spheres in it, no shapes_*.vtu are written.
  explicit VtkOutput(std::filesystem::path directory, std::vector<CompositeShape> shapes = {},
                     MeshResolution resolution = {});

  // Writes one frame at snapshot.time; walls are clipped to the snapshot's domain.
  void write_frame(const Snapshot& snapshot, const std::vector<Wall>& walls);
  // One frame of a run spread over `ranks` ranks, called on every rank with its piece
  // (World::snapshot_piece: its `owned` particles first, then the partners its contacts reach).
  // Each rank writes its pieces; once `all_written` returns (it must wait for every rank), rank
  // 0 writes the .pvtu files that join them, the walls, and the series.
  void write_frame_piece(const Snapshot& piece, std::size_t owned, const std::vector<Wall>& walls, int rank,
                         int ranks, const std::function<void()>& all_written);
  // A resumed run: frames go on from times.size(); the series list the earlier frames whose
  // files are in the directory (all of them when the run resumes in its own folder).
  void resume(const std::vector<double>& times);

  std::size_t frames() const { return frames_; }
  const std::filesystem::path& directory() const { return directory_; }

 private:
  std::filesystem::path frame_file(const char* stem) const { return frame_file(stem, frames_); }
  std::filesystem::path frame_file(const char* stem, std::size_t frame, const char* extension = "vtu") const;
  std::filesystem::path piece_file(const char* stem, int rank) const;

  std::filesystem::path directory_;
  std::vector<CompositeShape> shapes_;
  MeshResolution resolution_;
  PvdSeries particles_, contacts_, walls_;
  std::optional<PvdSeries> shapes_series_;
  std::size_t frames_ = 0;
};

}  // namespace talus::io
