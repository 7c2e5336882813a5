#include "shape_pile.h"

#include <omp.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "load_average.h"
#include "shape_pile_cases.h"
#include "shape_pile_states.h"
#include "talus/world/world.h"

namespace talus::bench {

namespace {

using Clock = std::chrono::steady_clock;
constexpr std::uint64_t kWarmSteps = 2000;  // after loading: rebuilds the tangential memory the cache does not hold

// Bodies touching a body, on average: contact points count a face contact up to four times
// (manifolds) and a tetrapod's arms each, this counts each touching pair once.
double touching_per_particle(const World& w) {
  std::set<std::pair<int, int>> pairs;
  for (const ContactRecord& r : w.snapshot().contacts)
    if (r.j >= 0) pairs.insert({std::min(r.i, r.j), std::max(r.i, r.j)});
  return 2.0 * static_cast<double>(pairs.size()) / static_cast<double>(w.owned_count());
}

struct StateFigures {
  PileTiming one, two;
  double contacts = 0, touching = 0;  ///< per particle
};

struct Figures {
  std::string name;
  StateFigures settled, flowing;
  bool flowed = false;
};

// A loaded state warmed up, then timed and profiled: METRIC lines <x>_<state>_1t and so on.
StateFigures time_state(World& w, const ShapePileOptions& o, const std::string& x, const std::string& state,
                        int threads, MetricSink metric) {
  const std::string p = x + "_" + state;
  auto m = [&](const char* suffix, double v, const char* unit) { metric((p + suffix).c_str(), v, unit); };
  omp_set_num_threads(threads);
  w.run(kWarmSteps);
  const Diagnostics d = w.diagnostics();
  const double n = static_cast<double>(w.owned_count());
  StateFigures f;
  f.contacts = 2.0 * static_cast<double>(d.contacts) / n;
  f.touching = touching_per_particle(w);
  m("_contacts_per_particle", f.contacts, "count");
  m("_touching_per_particle", f.touching, "count");
  m("_wall_contacts_per_particle", static_cast<double>(d.wall_contacts) / n, "count");
  m("_max_speed", d.max_speed, "m/s");
  m("_mean_speed", d.mean_speed, "m/s");
  const std::array<PileTiming, 2> timed = time_one_and_two_threads(w, o.steps, o.reps);
  f.one = timed[0];
  f.two = timed[1];
  m("_1t", f.one.wall, "us");
  m("_1t_cpu", f.one.cpu, "us");
  m("_2t", f.two.wall, "us");
  m("_speedup_2t", f.one.wall / f.two.wall, "x");
  profile_pile(w, o.steps, p, metric);
  return f;
}

Figures run_pile(const ShapePileOptions& o, const ShapePileCase& c, int threads, MetricSink metric) {
  const std::string x = "shapes_" + c.name;
  auto m = [&](const char* suffix, double v, const char* unit) { metric((x + suffix).c_str(), v, unit); };
  const auto start = Clock::now();
  Figures f;
  f.name = c.name;
  omp_set_num_threads(o.gen_threads > 0 ? o.gen_threads : threads);
  double generating = 0;
  auto w = load_or_settle(o, c, &generating);
  if (generating > 0) m("_settle_seconds", generating, "s");
  m("_particles", static_cast<double>(w->owned_count()), "count");
  f.settled = time_state(*w, o, x, "static", threads, metric);
  if (!o.static_only) {
    omp_set_num_threads(o.gen_threads > 0 ? o.gen_threads : threads);
    w = load_or_flow(o, c, &generating);
    if (generating > 0) m("_flow_seconds", generating, "s");
    f.flowing = time_state(*w, o, x, "flow", threads, metric);
    f.flowed = true;
  }
  std::fprintf(stderr, "[shapes %s] done in %.0f s\n", c.name.c_str(),
               std::chrono::duration<double>(Clock::now() - start).count());
  return f;
}

// The figures again, one line each: "shapes <case>_<state>_<threads>t  us/particle-step = ...".
void print_summary(const std::vector<Figures>& all) {
  auto line = [](const std::string& name, const char* state, const StateFigures& s) {
    for (int threads = 1; threads <= 2; ++threads)
      std::printf("shapes %-24s us/particle-step = %7.3f   contact points/particle = %5.2f   touching/particle = %5.2f\n",
                  (name + "_" + state + "_" + std::to_string(threads) + "t").c_str(),
                  threads == 1 ? s.one.wall : s.two.wall, s.contacts, s.touching);
  };
  for (const Figures& f : all) {
    line(f.name, "static", f.settled);
    if (f.flowed) line(f.name, "flow", f.flowing);
  }
  std::fflush(stdout);
}

}  // namespace

void run_shape_piles(const ShapePileOptions& o, MetricSink metric) {
  std::vector<ShapePileCase> chosen;
  for (ShapePileCase& c : shape_pile_cases())
    if (o.shape.empty() || o.shape == c.name) chosen.push_back(std::move(c));
  if (chosen.empty()) throw std::invalid_argument("--shape takes icosahedra, hexapods or tetrapods");
  const int threads = omp_get_max_threads();
  std::vector<Figures> all;
  for (const ShapePileCase& c : chosen) all.push_back(run_pile(o, c, threads, metric));
  metric("shapes_loadavg", load_average(), "load");
  print_summary(all);
  omp_set_num_threads(threads);
}

}  // namespace talus::bench
