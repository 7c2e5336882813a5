#include "shape_pile_states.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "chute_state.h"

namespace talus::bench {

namespace {

using Clock = std::chrono::steady_clock;
constexpr std::uint32_t kVersion = 1;  // of the recipes here and in shape_pile_cases.cpp: bump when they change
constexpr std::uint64_t kSeed = 1;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

std::uint64_t steps_of(double seconds, const ShapePileCase& c) {
  return std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::llround(seconds / c.time_step)));
}

std::uint64_t settle_steps(const ShapePileOptions& o, const ShapePileCase& c) {
  return steps_of(o.time_scale * c.settle_time, c);
}

std::uint64_t flow_steps(const ShapePileOptions& o, const ShapePileCase& c) {
  return steps_of(o.time_scale * c.flow_time, c);
}

std::filesystem::path cache_file(const ShapePileOptions& o, const ShapePileCase& c, const std::string& flow) {
  char name[200];
  std::snprintf(name, sizeof name, "shapes_%s_%zu_%llu%s_v%u.bin", c.name.c_str(), o.count,
                static_cast<unsigned long long>(settle_steps(o, c)), flow.c_str(), kVersion);
  return o.cache / name;
}

std::filesystem::path settled_file(const ShapePileOptions& o, const ShapePileCase& c) { return cache_file(o, c, ""); }

std::filesystem::path flowing_file(const ShapePileOptions& o, const ShapePileCase& c) {
  return cache_file(o, c, "_flow" + std::to_string(flow_steps(o, c)));
}

// The x+ wall (index 1) goes now: the pile slumps out of the box.
void open_side(World& w) {
  Wall& side = w.walls_mutable()[1];
  side.motion.kind = WallMotion::Kind::removed;
  side.motion.start_time = w.time();
}

void report(const ShapePileCase& c, const World& w, Clock::time_point t0) {
  const Diagnostics d = w.diagnostics();
  std::fprintf(stderr, "[shapes %s] t = %.3f s  largest speed %.3g m/s  mean %.3g m/s  contacts %zu  (%.0f s)\n",
               c.name.c_str(), w.time(), d.max_speed, d.mean_speed, d.contacts + d.wall_contacts, seconds_since(t0));
}

// `steps` steps in ten batches, each followed by a progress line.
void run_reporting(World& w, const ShapePileCase& c, std::uint64_t steps, Clock::time_point t0) {
  const std::uint64_t batch = std::max<std::uint64_t>(1, steps / 10);
  for (std::uint64_t done = 0; done < steps; done += batch) {
    w.run(std::min(batch, steps - done));
    report(c, w, t0);
  }
}

void save(const World& w, const ShapePileCase& c, const std::filesystem::path& file) {
  save_state(w, file);
  std::fprintf(stderr, "[shapes %s] cached %s\n", c.name.c_str(), file.c_str());
}

}  // namespace

std::unique_ptr<World> load_or_settle(const ShapePileOptions& o, const ShapePileCase& c, double* seconds_generating) {
  *seconds_generating = 0;
  const std::filesystem::path file = settled_file(o, c);
  if (!std::filesystem::exists(file)) {
    const auto t0 = Clock::now();
    auto w = make_shape_pile_world(c);
    const double top = fill_shape_pile(*w, c, o.count, kSeed);
    std::fprintf(stderr, "[shapes %s] placed %zu up to z = %.3f m in %.1f s\n", c.name.c_str(), w->owned_count(), top,
                 seconds_since(t0));
    run_reporting(*w, c, settle_steps(o, c), t0);
    save(*w, c, file);
    *seconds_generating = seconds_since(t0);
  }
  return load_state(make_shape_pile_world(c), file);
}

std::unique_ptr<World> load_or_flow(const ShapePileOptions& o, const ShapePileCase& c, double* seconds_generating) {
  *seconds_generating = 0;
  const std::filesystem::path file = flowing_file(o, c);
  if (!std::filesystem::exists(file)) {
    double settling = 0;
    auto w = load_or_settle(o, c, &settling);
    const auto t0 = Clock::now();
    open_side(*w);
    run_reporting(*w, c, flow_steps(o, c), t0);
    save(*w, c, file);
    *seconds_generating = settling + seconds_since(t0);
  }
  auto w = load_state(make_shape_pile_world(c), file);
  open_side(*w);  // the file keeps the particles, not the walls
  return w;
}

}  // namespace talus::bench
