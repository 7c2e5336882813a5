#pragma once
// Coarse graining of a finished run from its snapshot files (run.snapshot_interval): the fields
// of Weinhart et al. 2012, Sect. 3, on any 1D, 2D or 3D grid, averaged over the snapshots inside
// a time window (Eq. 43). What `talus coarse-grain DIR` runs.
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "talus/analysis/cg_fields.h"
#include "talus/analysis/cg_function.h"
#include "talus/analysis/cg_grid.h"

namespace talus {

// "AXIS=LO:HI:N" per resolved axis (x, y or z; e.g. "z=0:40:200"): N points from LO to HI
// inclusive, in the run's length unit; unnamed axes are averaged over the box. Throws
// std::invalid_argument naming the bad text.
CgGrid parse_cg_grid(const std::vector<std::string>& axes);

struct SavedCoarseGraining {
  CgFields mean;                 ///< time average over the snapshots used (Eq. 43)
  int snapshots = 0;             ///< files inside the window
  double first_time = 0, last_time = 0;
  double read_seconds = 0;       ///< wall time reading files
  double coarse_grain_seconds = 0;  ///< wall time coarse graining
};

// Averages the fields of every snapshot of `results_dir` whose time lies in [from, to].
// Throws std::runtime_error when the folder has no snapshots or none in the window.
SavedCoarseGraining coarse_grain_saved(const std::filesystem::path& results_dir, const CgGrid& grid,
                                       const CgFunction& function, double from = 0,
                                       double to = std::numeric_limits<double>::infinity());

// The averaged fields as CSV: the resolved coordinates, then density, momentum, velocity, the
// stress (total, kinetic, contact, boundary; nine components each, xx xy xz yx ...) and the
// boundary force density. Written atomically.
void write_cg_fields_csv(const std::filesystem::path& path, const CgFields& fields);

}  // namespace talus
