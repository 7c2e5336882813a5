#pragma once
// The benchmark's flowing chute states: a World rebuilt from a cached particle state, and the
// small versioned binary file that holds one. Contact memory is not cached: a benchmark warms
// the loaded world up for a few hundred steps before it times anything.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "talus/scenario/chute.h"
#include "talus/world/world.h"

namespace talus::bench {

// One benchmark chute: the Weinhart et al. 2012 Sect. 5 set-up, flowed for `flow_time`.
struct ChuteCase {
  std::string name;         ///< METRIC prefix, e.g. "chute4k"
  ChuteSetup setup;
  double flow_time = 10;    ///< sqrt(d/g), how long the cached state has flowed down the slope
};

// The case's chute: Weinhart contact for flow-flow and flow-base, `length` x `width`, H, theta.
ChuteCase make_case(const std::string& name, double length, double width, double fill_height, double flow_time);

// The chute's flow under Hertz-Mindlin (Tsuji dashpots, eta_t = eta_n, unclamped as Weinhart's
// Eq. 3), with the linear law's contact time at an impact of sqrt(g d) and its restitution 0.883.
ContactParams hertz_mindlin_chute_contact();

// An empty World with the settings and contact table that build_chute(s) gives its world.
// The same as make_chute_world (src/talus/scenario/chute.h).
std::unique_ptr<World> make_empty_chute_world(const ChuteSetup& s);

// Cache file of a case, keyed by every set-up parameter (a hash covers the contact law).
std::filesystem::path cache_path(const std::filesystem::path& dir, const ChuteCase& c);

// Writes the owned particles of `world` (in global-id order) and its time, atomically.
void save_state(const World& world, const std::filesystem::path& file);
// A world rebuilt from `file` with make_empty_chute_world(c.setup); throws if the file is
// missing, of another version, or corrupt.
std::unique_ptr<World> load_state(const ChuteCase& c, const std::filesystem::path& file);
// The same into any empty world with the settings, shapes and contact table of the saved one.
std::unique_ptr<World> load_state(std::unique_ptr<World> empty, const std::filesystem::path& file);

// The case's state repeated tiles_x x tiles_y times over a base that many times longer and wider:
// the chute is periodic along both, so the copies join into one flowing state of the larger
// chute at once (the 10^6-sphere runs, which could not be flowed from rest in minutes).
std::unique_ptr<World> load_state_tiled(const ChuteCase& c, const std::filesystem::path& file, int tiles_x,
                                        int tiles_y);

// The cached world of a case, generating the cache first if needed (build_chute, then run
// until t = flow_time on `threads` OpenMP threads; progress goes to stderr).
std::unique_ptr<World> load_or_generate(const ChuteCase& c, const std::filesystem::path& dir, int threads,
                                        double* seconds_generating);

}  // namespace talus::bench
