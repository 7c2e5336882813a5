#pragma once
// Timing a pile of shaped bodies, shared by the cross pile (cross_pile.h) and the shape piles
// (shape_pile.h): 1 and 2 threads taking turns, and a one-thread run with the composite
// counters on that says where the time goes.
#include <array>
#include <cstdint>
#include <string>

#include "talus/world/world.h"

namespace talus::bench {

using MetricSink = void (*)(const char* name, double value, const char* unit);

struct PileTiming {
  double wall = 1e300;  ///< fastest of the repetitions, us per particle-step
  double cpu = 1e300;   ///< process CPU time of that repetition, us per particle-step
};

// Fastest of `reps` runs of `steps` steps on 1 and on 2 threads (after 200 untimed steps), the
// two taking turns within each repetition so that both see the same machine: its speed drifts
// by tens of per cent over a minute. On one thread the CPU time is what the step costs when
// other jobs keep the thread waiting for a core.
std::array<PileTiming, 2> time_one_and_two_threads(World& w, std::uint64_t steps, int reps);

// `steps` steps on one thread with the counters on (after 50 untimed): prints <prefix> followed
// by _body_pairs_per_particle_step, _part_pair_tests_per_particle_step,
// _narrow_phase_per_particle_step, _reuse_share (box part pairs in the narrow phase served from
// their stored feature), _full_box_queries_per_particle_step and the _share_* of broad phase,
// narrow phase, force model, walls, integration and the culls inside the pair loop.
void profile_pile(World& w, std::uint64_t steps, const std::string& prefix, MetricSink metric);

}  // namespace talus::bench
