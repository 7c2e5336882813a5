// Google Benchmark micro-benchmarks of the contact-force kernel (src/talus/contact/contact_law.h),
// run by `talus-bench --micro [--benchmark_* flags]`.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "talus/contact/contact_law.h"
#include "talus/scenario/chute.h"

namespace talus::bench {
namespace {

struct KernelInput {
  ContactGeometry geometry;
  ContactMotion motion;
};

// Chute-like contacts: overlaps up to 1e-3 d, speeds ~ sqrt(g d), some sliding.
std::vector<KernelInput> make_inputs(std::size_t n) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<KernelInput> in(n);
  for (KernelInput& k : in) {
    const Vec3 n3 = normalized_or_zero(Vec3{u(rng), u(rng), u(rng)});
    k.geometry.normal = n3;
    k.geometry.overlap = 5e-4 * (1 + u(rng));
    k.geometry.arm_i = n3 * -(0.5 - 0.5 * k.geometry.overlap);
    k.geometry.arm_j = n3 * (0.5 - 0.5 * k.geometry.overlap);
    k.geometry.inv_distance = 1 / (1 - k.geometry.overlap);
    k.motion = {{u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}};
  }
  return in;
}

template <TangentialModel Model>
void BM_contact_force(benchmark::State& state) {
  const ContactParams params = weinhart_chute_contact();
  const std::vector<KernelInput> in = make_inputs(1024);
  std::vector<Vec3> spring(in.size()), normal_prev(in.size());
  const double dt = 1e-4;
  Vec3 sum;
  for (auto _ : state) {
    for (std::size_t k = 0; k < in.size(); ++k) {
      const ContactHistoryRef h{&spring[k], Model == TangentialModel::memory ? &normal_prev[k] : nullptr, nullptr};
      const ContactResult r = contact_force<Model>(in[k].geometry, in[k].motion, params, 0.5, 0.25, dt, h);
      sum += r.force_on_i;
    }
    benchmark::DoNotOptimize(sum);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * in.size()));  // contacts
}

BENCHMARK(BM_contact_force<TangentialModel::elastic_spring>);
BENCHMARK(BM_contact_force<TangentialModel::memory>);
BENCHMARK(BM_contact_force<TangentialModel::memoryless>);

}  // namespace
}  // namespace talus::bench
