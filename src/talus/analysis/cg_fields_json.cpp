#include "talus/analysis/cg_fields_json.h"

#include <stdexcept>

namespace talus {
namespace {

// Per point: density, momentum (3), boundary force (3), then the four tensors row by row.
constexpr std::size_t kPerPoint = 1 + 3 + 3 + 4 * 9;

}  // namespace

nlohmann::json to_json(const CgFields& fields) {
  const CgGrid& g = fields.grid;
  nlohmann::json grid = {{"resolved", {g.resolved[0], g.resolved[1], g.resolved[2]}},
                         {"n", {g.n[0], g.n[1], g.n[2]}},
                         {"lo", {g.lo[0], g.lo[1], g.lo[2]}},
                         {"hi", {g.hi[0], g.hi[1], g.hi[2]}}};
  std::vector<double> v;
  v.reserve(fields.values.size() * kPerPoint);
  for (const CgValues& c : fields.values) {
    v.push_back(c.density);
    for (int a = 0; a < 3; ++a) v.push_back(c.momentum[a]);
    for (int a = 0; a < 3; ++a) v.push_back(c.boundary_force[a]);
    for (const Eigen::Matrix3d* m : {&c.momentum_flux, &c.kinetic_stress, &c.contact_stress, &c.boundary_stress})
      for (int r = 0; r < 3; ++r)
        for (int col = 0; col < 3; ++col) v.push_back((*m)(r, col));
  }
  return {{"grid", grid}, {"values", v}};
}

CgFields cg_fields_from_json(const nlohmann::json& j) {
  try {
    CgFields f;
    const nlohmann::json& g = j.at("grid");
    for (int a = 0; a < 3; ++a) {
      f.grid.resolved[a] = g.at("resolved").at(a).get<bool>();
      f.grid.n[a] = g.at("n").at(a).get<int>();
      f.grid.lo[a] = g.at("lo").at(a).get<double>();
      f.grid.hi[a] = g.at("hi").at(a).get<double>();
    }
    const std::vector<double> v = j.at("values").get<std::vector<double>>();
    if (f.grid.size() < 1 || v.size() != static_cast<std::size_t>(f.grid.size()) * kPerPoint)
      throw std::invalid_argument("cg fields: values do not match the grid");
    f.values.resize(f.grid.size());
    std::size_t k = 0;
    for (CgValues& c : f.values) {
      c.density = v[k++];
      for (int a = 0; a < 3; ++a) c.momentum[a] = v[k++];
      for (int a = 0; a < 3; ++a) c.boundary_force[a] = v[k++];
      for (Eigen::Matrix3d* m : {&c.momentum_flux, &c.kinetic_stress, &c.contact_stress, &c.boundary_stress})
        for (int r = 0; r < 3; ++r)
          for (int col = 0; col < 3; ++col) (*m)(r, col) = v[k++];
    }
    return f;
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(std::string("cg fields: ") + e.what());
  }
}

}  // namespace talus
