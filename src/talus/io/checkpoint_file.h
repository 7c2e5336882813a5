#pragma once
// Checkpoint files: the state of a World (world/world_state.h) and of the run around it, in
// HDF5 (open one with h5dump or h5py). Written through io::AtomicFile: a checkpoint on disk is
// always complete, and a run killed while writing one leaves only a `.tmp.<pid>` file behind.
//
// Layout, format version 1 (every dataset carries an fnv1a64 checksum attribute):
//   /                        attributes format = "talus-checkpoint", format_version, talus_version, step
//   /scenario                text: the scenario as run (overrides applied), TOML
//   /run                     text: JSON of the run loop, the pours and the observers
//   /timeseries              rows x columns: the time-series rows written so far
//   /timeseries_columns      text: JSON array of the column names
//   /world/counters          next_gid, steps, rebuilds, tangential model (0 memory, 1 memoryless, 2 elastic_spring)
//   /world/times             time, time of the last list build, skin, gravity x y z
//   /world/particles/*       position, velocity, angular_velocity, force, torque (n x 3),
//                            orientation (n x 4, w x y z), radius, inv_mass, mass, inv_inertia,
//                            species, shape, gid; owned particles in their current order
//   /world/position_at_build positions of the last neighbour-list build (n x 3)
//   /world/walls             text: JSON of the walls; /world/wall_force (walls x 3)
//   /contacts/pairs/*        gid (entries x 2), spring, normal_prev, rolling, and the
//                            contact points of rigid bodies (points/*)
//   /contacts/walls/*        gid, wall, force, spring, normal_prev, rolling, points/*
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "talus/world/world_state.h"

namespace talus::io {

inline constexpr int kCheckpointFormatVersion = 1;

struct Checkpoint {
  std::string talus_version = TALUS_VERSION;
  std::string scenario_toml;             ///< the scenario as run
  WorldState world;
  nlohmann::json run = nlohmann::json::object();  ///< run loop, pours, observers
  std::vector<std::string> timeseries_columns;
  std::vector<double> timeseries;        ///< rows written so far, row-major
};

// The file's bytes (what write_checkpoint puts on disk; `talus check` sizes a checkpoint by it).
std::vector<char> checkpoint_image(const Checkpoint& checkpoint);

// Writes atomically; throws std::system_error or std::runtime_error on failure.
void write_checkpoint(const std::filesystem::path& path, const Checkpoint& checkpoint);

// Throws io::InputError "PATH: what is wrong" for a missing, corrupt or foreign file, or one of
// another format version.
Checkpoint read_checkpoint(const std::filesystem::path& path);
// Rank `rank` of a run on `ranks` ranks: of a state gathered from as many ranks (its layout
// fits them), only this rank's share of the arrays (WorldState::share_of_rank), and unchecked
// against the checksums (rank 0 reads the file whole and checks it); otherwise the whole state.
Checkpoint read_checkpoint_share(const std::filesystem::path& path, int rank, int ranks);
// Only the scenario text stored in it (what `talus resume` needs before the run reads the state).
std::string read_checkpoint_scenario(const std::filesystem::path& path);

}  // namespace talus::io
