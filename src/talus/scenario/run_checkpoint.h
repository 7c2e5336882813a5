#pragma once
// A run in progress as a checkpoint, and back: the World (world/world_state.h), the run loop's
// own schedule and the time-series rows written so far, the pours (random generators and
// counters) and every RunObserver's state().
#include <limits>
#include <string>
#include <vector>

#include "talus/io/checkpoint_file.h"
#include "talus/parallel/communicator.h"
#include "talus/scenario/scenario.h"

namespace talus {

// What the run loop must carry across a restart besides the World.
struct LoopState {
  double next_output = 0;  ///< s, time of the next time-series row
  double next_frame = 0;   ///< s, time of the next VTK frame
  double next_checkpoint = std::numeric_limits<double>::infinity();  ///< s
  // s between checkpoints (0: only the final one). Carried so that a resumed run keeps the
  // cadence it was started with, which --checkpoint-interval may have set outside the scenario.
  double checkpoint_interval = 0;
  std::vector<double> vtk_times;  ///< s, of every VTK frame written
  double next_snapshot = 0;       ///< s, time of the next snapshot file
  std::size_t snapshots = 0;      ///< snapshot files written
  std::vector<double> rows;       ///< time-series rows written, row-major
  std::uint64_t particles_left_domain = 0;  ///< removed by domain.on_leave = "delete" (BlowUpGuard)
};

// The run's state now. The World may be prepared first (see World::capture_state).
io::Checkpoint capture_checkpoint(Scenario& scenario, const LoopState& loop, const std::string& scenario_toml,
                                  const std::vector<std::string>& columns);

// Puts the scenario's World, pours and observers into the checkpoint's state and returns the
// loop's. Throws io::InputError "SOURCE: what does not fit" when the checkpoint was written for
// another scenario (other walls, pours, observers, species or time-series columns). `ranks`: the
// ranks the run goes on over (World::restore_state): a checkpoint written on as many goes on
// spread as it was, bit for bit. The checkpoint is taken by value so that a caller done with it
// can move it in: its state then becomes the World's without a second copy.
LoopState restore_checkpoint(Scenario& scenario, io::Checkpoint checkpoint, const std::string& source,
                             const std::vector<std::string>& columns, const Communicator* ranks = nullptr);

}  // namespace talus
