// Google Benchmark micro-benchmarks of the narrow phase between convex parts, run by
// `talus-bench --micro --benchmark_filter=Narrow`: the crust method's GJK distance, EPA on
// intersecting cores, and the box-box separating-axis test with its manifold, on random
// posed pairs of boxes and polyhedra (the pairs of tests/test_convex_contact.cpp).
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "talus/collide/box_box.h"
#include "talus/collide/convex_contact.h"
#include "talus/collide/gjk.h"
#include "talus/collide/gjk_epa.h"
#include "talus/collide/manifold.h"
#include "talus/shape/convex_shape.h"

namespace talus::bench {
namespace {

struct PosedPair {
  ConvexShape a, b;
  Pose pa, pb;
};

Quat random_quat(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  return Quat{g(rng), g(rng), g(rng), g(rng)}.normalized();
}

ConvexShape random_shape(std::mt19937_64& rng, bool polyhedron) {
  std::uniform_real_distribution<double> u(0.5, 1.5);
  std::normal_distribution<double> g;
  if (!polyhedron) {
    const Vec3 h{u(rng), u(rng), u(rng)};
    return make_box(h, 0.1 * std::min({h.x, h.y, h.z}));
  }
  const Vec3 axes{u(rng), u(rng), u(rng)};
  std::vector<Vec3> pts = {{axes.x, 0, 0}, {-axes.x, 0, 0}, {0, axes.y, 0}, {0, -axes.y, 0}, {0, 0, axes.z}, {0, 0, -axes.z}};
  for (int i = 0; i < 12; ++i) pts.push_back(hadamard(normalized_or_zero({g(rng), g(rng), g(rng)}), axes));
  return make_polyhedron(pts, 0.08);
}

// Pairs whose cores are within the crusts (deep = false: GJK answers) or intersect (deep =
// true: EPA answers), found by rejection.
std::vector<PosedPair> make_pairs(bool polyhedra, bool deep, std::size_t n) {
  std::mt19937_64 rng(deep ? 21 : 22);
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> g;
  // A few shapes, many poses: building a polyhedron (three hulls) costs more than the queries.
  std::vector<ConvexShape> shapes_a, shapes_b;
  for (int k = 0; k < 8; ++k) shapes_a.push_back(random_shape(rng, polyhedra)), shapes_b.push_back(random_shape(rng, false));
  std::vector<PosedPair> out;
  while (out.size() < n) {
    PosedPair p{shapes_a[out.size() % 8], shapes_b[(out.size() / 8) % 8], {}, {}};
    p.pa = {{0, 0, 0}, random_quat(rng)};
    const double reach = p.a.bounding_radius + p.b.bounding_radius;
    p.pb = {normalized_or_zero({g(rng), g(rng), g(rng)}) * (reach * (0.3 + 0.7 * u(rng))), random_quat(rng)};
    const PartContact c = crust_contact(p.a, p.pa, p.b, p.pb);
    if (c.touching && (c.method == ContactMethod::kCrustEpa) == deep) out.push_back(p);
  }
  return out;
}

void run_crust(benchmark::State& state, bool polyhedra, bool deep) {
  const std::vector<PosedPair> pairs = make_pairs(polyhedra, deep, 256);
  double sum = 0;
  for (auto _ : state) {
    for (const PosedPair& p : pairs) sum += crust_contact(p.a, p.pa, p.b, p.pb).delta_n;
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * pairs.size()));  // queries
}

void BM_Narrow_crust_gjk_box_box(benchmark::State& s) { run_crust(s, false, false); }
void BM_Narrow_crust_gjk_poly_box(benchmark::State& s) { run_crust(s, true, false); }
void BM_Narrow_crust_epa_box_box(benchmark::State& s) { run_crust(s, false, true); }
void BM_Narrow_crust_epa_poly_box(benchmark::State& s) { run_crust(s, true, true); }

// Touching pairs of Huet cross arms (27 x 2 x 3 mm boxes) in random poses.
std::vector<std::pair<OrientedBox, OrientedBox>> touching_arms() {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> u(-1, 1);
  const Vec3 h{13.5e-3, 1e-3, 1.5e-3};
  std::vector<std::pair<OrientedBox, OrientedBox>> pairs;
  while (pairs.size() < 256) {
    const OrientedBox a = oriented_box(h, Pose{{}, random_quat(rng)});
    const OrientedBox b = oriented_box(h, Pose{{u(rng) * 0.01, u(rng) * 0.01, u(rng) * 0.004}, random_quat(rng)});
    if (!box_box_sat(a, b).separated) pairs.emplace_back(a, b);
  }
  return pairs;
}

// SAT + clipping, as a touching part pair of two crosses costs.
void BM_Narrow_box_box_sat_manifold(benchmark::State& state) {
  const auto pairs = touching_arms();
  double sum = 0;
  for (auto _ : state) {
    for (const auto& [a, b] : pairs) {
      const BoxBoxSat sat = box_box_sat(a, b);
      sum += box_box_manifold(a, b, sat).count;
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * pairs.size()));
}

// The axis test alone.
void BM_Narrow_box_box_sat(benchmark::State& state) {
  const auto pairs = touching_arms();
  double sum = 0;
  for (auto _ : state) {
    for (const auto& [a, b] : pairs) sum += box_box_sat(a, b).depth;
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * pairs.size()));
}

BENCHMARK(BM_Narrow_crust_gjk_box_box);
BENCHMARK(BM_Narrow_crust_gjk_poly_box);
BENCHMARK(BM_Narrow_crust_epa_box_box);
BENCHMARK(BM_Narrow_crust_epa_poly_box);
BENCHMARK(BM_Narrow_box_box_sat_manifold);
BENCHMARK(BM_Narrow_box_box_sat);

}  // namespace
}  // namespace talus::bench
