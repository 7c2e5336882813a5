#include "cross_pile.h"

#include <omp.h>

#include <chrono>
#include <cstdio>
#include <memory>

#include "chute_state.h"
#include "load_average.h"
#include "pile_timing.h"
#include "talus/scenario/cross_box.h"
#include "talus/world/composite_stats.h"
#include "talus/world/world.h"

namespace talus::bench {

namespace {

using Clock = std::chrono::steady_clock;
constexpr std::uint32_t kVersion = 2;  // of the generation recipe below (and of the cross's inertia): bump when it changes

CrossBoxSetup pile_setup(const CrossPileOptions& o) {
  CrossBoxSetup s;
  s.count = o.crosses;
  s.box = {0.2, 0.2, 0.05};     // 20 x 20 cm floor
  s.domain_hi = {1.0, 0.2, 1.0};  // room for the flow past x = 0.2 m
  s.narrow_phase_reuse = o.narrow_phase_reuse;
  s.manifold_refit = o.manifold_refit;
  s.manifold_recycle = o.manifold_recycle;
  return s;
}

std::filesystem::path pile_cache(const CrossPileOptions& o) {
  char name[128];
  std::snprintf(name, sizeof name, "crosspile_%zu_v%u.bin", o.crosses, kVersion);
  return o.cache / name;
}

// Dense random placement (exact part tests), then settling under gravity until the fastest
// cross is slower than settle_speed.
std::unique_ptr<World> settle_pile(const CrossPileOptions& o) {
  auto w = make_cross_box_world(pile_setup(o));
  const auto t0 = Clock::now();
  const double top = fill_cross_box(*w, pile_setup(o));
  std::fprintf(stderr, "[crosspile] placed %zu crosses up to z = %.3f m in %.1f s\n", w->owned_count(), top,
               std::chrono::duration<double>(Clock::now() - t0).count());
  while (w->time() < o.settle_time_limit) {
    w->run(4000);
    const Diagnostics d = w->diagnostics();
    std::fprintf(stderr, "[crosspile] t = %.3f s  largest speed %.3g m/s  contacts %zu  (%.0f s)\n", w->time(),
                 d.max_speed, d.contacts + d.wall_contacts, std::chrono::duration<double>(Clock::now() - t0).count());
    if (w->time() > 0.1 && d.max_speed < o.settle_speed) break;
  }
  return w;
}

std::unique_ptr<World> load_or_settle(const CrossPileOptions& o, double* seconds) {
  *seconds = 0;
  const std::filesystem::path file = pile_cache(o);
  if (!std::filesystem::exists(file)) {
    const auto t0 = Clock::now();
    auto w = settle_pile(o);
    save_state(*w, file);
    *seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    std::fprintf(stderr, "[crosspile] cached %s\n", file.c_str());
  }
  // Contact memory is not cached: the warm-up of each timing rebuilds it.
  return load_state(make_cross_box_world(pile_setup(o)), file);
}

}  // namespace

void run_cross_pile(const CrossPileOptions& o, void (*metric)(const char*, double, const char*)) {
  const int threads = omp_get_max_threads();
  double generating = 0;
  auto w = load_or_settle(o, &generating);
  if (generating > 0) metric("crosspile_settle_seconds", generating, "s");
  const double n = static_cast<double>(w->owned_count());
  metric("crosspile_particles", n, "count");
  omp_set_num_threads(threads);
  w->run(2000);  // rebuild the tangential memory the cache does not hold
  const Diagnostics settled = w->diagnostics();
  metric("crosspile_contacts_per_particle", 2.0 * static_cast<double>(settled.contacts) / n, "count");
  metric("crosspile_wall_contacts_per_particle", static_cast<double>(settled.wall_contacts) / n, "count");
  metric("crosspile_static_max_speed", settled.max_speed, "m/s");
  const auto [s1, s2] = time_one_and_two_threads(*w, o.steps, o.reps);
  metric("crosspile_static_1t", s1.wall, "us");
  metric("crosspile_static_1t_cpu", s1.cpu, "us");
  metric("crosspile_static_2t", s2.wall, "us");
  metric("crosspile_static_speedup_2t", s1.wall / s2.wall, "x");
  profile_pile(*w, o.steps, "crosspile_static", metric);
  {
    const CompositeStats st = composite_stats_total();  // of that profile run
    const double q = static_cast<double>(st.box_full_queries + st.box_reused);
    metric("crosspile_reuse_share", q > 0 ? st.box_reused / q : 0.0, "fraction");
    metric("crosspile_refit_share", q > 0 ? st.box_refit / q : 0.0, "fraction");
    metric("crosspile_recycle_share", q > 0 ? st.box_recycled / q : 0.0, "fraction");
  }
  if (o.static_only) return;
  // Flowing: the x+ wall goes, the pile slumps out of the box.
  Wall& side = w->walls_mutable()[1];
  side.motion.kind = WallMotion::Kind::removed;
  side.motion.start_time = w->time();
  omp_set_num_threads(threads);
  w->run(20000);  // 0.05 s: the front is moving
  metric("crosspile_flow_mean_speed", w->diagnostics().mean_speed, "m/s");
  const auto [f1, f2] = time_one_and_two_threads(*w, o.steps, o.reps);
  metric("crosspile_flow_1t", f1.wall, "us");
  metric("crosspile_flow_1t_cpu", f1.cpu, "us");
  metric("crosspile_flow_2t", f2.wall, "us");
  metric("crosspile_flow_speedup_2t", f1.wall / f2.wall, "x");
  const Diagnostics flowing = w->diagnostics();
  metric("crosspile_flow_contacts_per_particle", 2.0 * static_cast<double>(flowing.contacts) / n, "count");
  profile_pile(*w, o.steps, "crosspile_flow", metric);
  metric("crosspile_loadavg", load_average(), "load");
  omp_set_num_threads(threads);
}

}  // namespace talus::bench
