#include "talus/world/state_guard.h"

#include <limits>

#include "talus/world/parallel.h"

namespace talus {

GuardBounds::GuardBounds(const Domain& domain, double time_step) : dt2(time_step * time_step) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a) {
    lo[a] = domain.periodic[a] ? -kInf : domain.lo[a];
    hi[a] = domain.periodic[a] ? kInf : domain.hi[a];
  }
}

unsigned scan_state(const ParticleStore& p, const Domain& domain, double time_step) {
  const GuardBounds bounds(domain, time_step);
  const long n = static_cast<long>(p.owned);
  unsigned faults = 0;
#pragma omp parallel for schedule(static) reduction(| : faults) if (worth_parallel(p.owned))
  for (long i = 0; i < n; ++i) faults |= particle_faults(p, static_cast<std::size_t>(i), bounds);
  return faults;
}

std::vector<std::uint32_t> particles_with(const ParticleStore& p, const Domain& domain, double time_step,
                                          StateFault fault) {
  const GuardBounds bounds(domain, time_step);
  std::vector<std::uint32_t> found;
  for (std::size_t i = 0; i < p.owned; ++i)
    if (particle_faults(p, i, bounds) & fault) found.push_back(static_cast<std::uint32_t>(i));
  return found;
}

}  // namespace talus
