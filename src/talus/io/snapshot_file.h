#pragma once
// Snapshots on disk: everything an analysis reads (analysis/snapshot.h), particles and contacts,
// in HDF5 (open one with h5dump or h5py), so coarse graining and the other analyses run on saved
// output exactly as on a live run. Written through io::AtomicFile: all or nothing.
//
// Layout, format version 1 (every dataset carries an fnv1a64 checksum attribute):
//   /                     attributes format = "talus-snapshot", format_version, talus_version
//   /frame                time, gravity x y z, domain_min x y z, domain_max x y z
//   /periodic             three 0/1 flags (x, y, z)
//   /particles/*          id (UInt32), species, shape, fixed (Int32), mass, radius, volume,
//                         position, velocity, angular_velocity (n x 3), orientation (n x 4, w x y z)
//   /contacts/*           i, j, wall (Int32; j = -1 for a wall contact), point, normal, force
//                         (n x 3, force on i), overlap
#include <filesystem>
#include <string>
#include <vector>

#include "talus/analysis/snapshot.h"

namespace talus::io {

inline constexpr int kSnapshotFormatVersion = 1;

// "snapshot_NNNNNN.h5": the index-th file of a run's snapshots/ folder.
std::string snapshot_file_name(std::size_t index);

// The snapshot files of a results folder (DIR/snapshots/snapshot_*.h5) in the order written;
// empty when there are none.
std::vector<std::filesystem::path> snapshot_files(const std::filesystem::path& results_dir);

// Writes atomically; throws std::system_error or std::runtime_error on failure.
void write_snapshot_file(const std::filesystem::path& path, const Snapshot& snapshot);

// Throws io::InputError "PATH: what is wrong" for a missing, corrupt or foreign file.
Snapshot read_snapshot_file(const std::filesystem::path& path);

}  // namespace talus::io
