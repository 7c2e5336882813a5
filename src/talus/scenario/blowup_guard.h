#pragma once
// The run loop's blow-up guard: after every batch of steps (at most 64, and at every output step)
// it looks for particles in states no valid step leads to (world/state_guard.h: not finite,
// moving more than a radius or turning more than a radian per step, outside a non-periodic face
// of the domain). Such a state stops the run with an error that names the step, the particles
// and the quantity; a particle that left the domain is instead removed and counted when the
// scenario says `domain.on_leave = "delete"`.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "talus/world/world.h"

namespace talus {

// What happens to a particle that leaves the domain through a non-periodic face (domain.on_leave).
enum class LeavePolicy {
  error,   ///< the run stops, as for any other blow-up
  remove,  ///< "delete": the particle is removed from the world and counted
};

// What stopped a run that blew up.
struct BlowUp {
  std::uint64_t step = 0;
  double time = 0;                       ///< s
  std::string quantity;                  ///< "position", "velocity", "angular_velocity", "force", "speed", "spin"
  std::vector<std::uint32_t> particles;  ///< global ids of every offending particle, ascending
  std::string message;                   ///< one line: step, time, particles, quantity
  nlohmann::json particle_states;        ///< the first offending particles' full states
};

class BlowUpGuard {
 public:
  explicit BlowUpGuard(LeavePolicy on_leave) : on_leave_(on_leave) {}
  // Checks the world's state. With LeavePolicy::remove the particles that left the domain are
  // removed (and counted) unless something worse is wrong. Returns what must stop the run.
  // A distributed world's ranks all stop if one finds a fault, and count removals over all ranks.
  std::optional<BlowUp> check(World& world);
  // Particles removed so far, this run and the runs it was restarted from.
  std::uint64_t removed() const { return removed_; }
  void set_removed(std::uint64_t n) { removed_ = n; }  ///< from a checkpoint

 private:
  std::optional<BlowUp> check_here(World& world);  ///< this rank's particles
  LeavePolicy on_leave_;
  std::uint64_t removed_ = 0;
};

// The file the state of a blown-up run goes to, in the results folder (a snapshot file,
// io/snapshot_file.h, so h5py and the analyses read it).
inline constexpr const char* kBlowUpStateFile = "blowup_state.h5";

// summary.json's record of a blow-up (non-finite numbers as the strings "nan", "inf", "-inf").
nlohmann::json blow_up_json(const BlowUp& blow_up);

}  // namespace talus
