#include "talus/analysis/cg_fields_sum.h"

#include <stdexcept>

namespace talus {
namespace {

// The additive part of one grid point: density, momentum, momentum flux, contact and boundary
// stresses, boundary force.
constexpr std::size_t kAdditive = 1 + 3 + 9 + 9 + 9 + 3;

template <class Fn>
void for_each_additive(CgValues& v, Fn&& fn) {
  fn(v.density);
  for (int a = 0; a < 3; ++a) fn(v.momentum[a]);
  for (Eigen::Matrix3d* m : {&v.momentum_flux, &v.contact_stress, &v.boundary_stress})
    for (int k = 0; k < 9; ++k) fn(m->data()[k]);
  for (int a = 0; a < 3; ++a) fn(v.boundary_force[a]);
}

}  // namespace

void sum_over_ranks(CgFields& fields, const Communicator& ranks) {
  if (!ranks.distributed()) return;
  std::vector<double> flat;
  flat.reserve(fields.values.size() * kAdditive + 1);
  flat.push_back(static_cast<double>(fields.values.size()));
  for (CgValues& v : fields.values) for_each_additive(v, [&](double& x) { flat.push_back(x); });
  // Grids that differ between ranks would sum unrelated points: the count must agree.
  const double points = flat.front();
  ranks.sum_in_place(flat);
  if (flat.front() != points * ranks.size()) throw std::logic_error("sum_over_ranks: the ranks' grids differ");
  std::size_t at = 1;
  for (CgValues& v : fields.values) {
    for_each_additive(v, [&](double& x) { x = flat[at++]; });
    v.form_kinetic_stress();
  }
}

}  // namespace talus
