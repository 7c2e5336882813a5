#include "talus/analysis/cg_time_average.h"

#include <stdexcept>

namespace talus {
namespace {

bool same_grid(const CgGrid& a, const CgGrid& b) {
  for (int k = 0; k < 3; ++k)
    if (a.resolved[k] != b.resolved[k] || a.n[k] != b.n[k] || a.lo[k] != b.lo[k] || a.hi[k] != b.hi[k])
      return false;
  return true;
}

}  // namespace

void CgTimeAverage::add(const CgFields& fields) {
  if (count_ == 0) {
    sum_ = fields;
    count_ = 1;
    return;
  }
  if (!same_grid(sum_.grid, fields.grid) || sum_.values.size() != fields.values.size())
    throw std::invalid_argument("CgTimeAverage: fields on a different grid");
  for (std::size_t k = 0; k < fields.values.size(); ++k) {
    CgValues& s = sum_.values[k];
    const CgValues& v = fields.values[k];
    s.density += v.density;
    s.momentum += v.momentum;
    s.momentum_flux += v.momentum_flux;
    s.kinetic_stress += v.kinetic_stress;
    s.contact_stress += v.contact_stress;
    s.boundary_stress += v.boundary_stress;
    s.boundary_force += v.boundary_force;
  }
  ++count_;
}

CgFields CgTimeAverage::mean() const {
  if (count_ == 0) throw std::logic_error("CgTimeAverage: no snapshots added");
  CgFields m = sum_;
  const double inv = 1.0 / count_;
  for (CgValues& v : m.values) {
    v.density *= inv;
    v.momentum *= inv;
    v.momentum_flux *= inv;
    v.kinetic_stress *= inv;
    v.contact_stress *= inv;
    v.boundary_stress *= inv;
    v.boundary_force *= inv;
  }
  return m;
}

}  // namespace talus
