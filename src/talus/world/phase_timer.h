#pragma once
// Wall-clock time spent in each phase of the step, for profiles and benchmarks.
#include <array>
#include <chrono>

namespace talus {

// exchange: the halo's every-step messages (ghost states forward, their forces back);
// migration: what a rebuild sends (the cuts rebalanced, particles and memories handed over, the
// halo made afresh); rebuild_vote: the ranks agreeing whether to rebuild. Each includes the
// time a rank ahead of the others waits for them there.
enum class Phase { integrate, neighbors, pair_forces, wall_forces, placement, exchange, rebuild_vote, migration, count };

// The name each phase has in a run's summary.json.
inline const char* phase_name(Phase p) {
  constexpr const char* kNames[] = {"integrate",  "neighbours", "pair_forces", "wall_forces",
                                    "placement", "exchange",   "rebuild_vote", "migration"};
  return kNames[static_cast<int>(p)];
}

class PhaseTimer {
 public:
  using Clock = std::chrono::steady_clock;
  void add(Phase p, Clock::duration d) { total_[static_cast<int>(p)] += d; }
  double seconds(Phase p) const { return std::chrono::duration<double>(total_[static_cast<int>(p)]).count(); }
  void reset() { total_.fill({}); }

 private:
  std::array<Clock::duration, static_cast<int>(Phase::count)> total_{};
};

// Adds the lifetime of a scope to one phase.
class ScopedPhase {
 public:
  ScopedPhase(PhaseTimer& t, Phase p) : timer_(t), phase_(p), start_(PhaseTimer::Clock::now()) {}
  ~ScopedPhase() { timer_.add(phase_, PhaseTimer::Clock::now() - start_); }

 private:
  PhaseTimer& timer_;
  Phase phase_;
  PhaseTimer::Clock::time_point start_;
};

}  // namespace talus
