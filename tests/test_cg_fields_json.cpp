// Coarse-grained fields survive a trip through JSON bit for bit (checkpointed time averages).
#include <gtest/gtest.h>

#include "talus/analysis/cg_fields_json.h"
#include "talus/analysis/cg_time_average.h"

namespace talus {
namespace {

TEST(CgFieldsJson, RoundTripIsExact) {
  CgFields f;
  f.grid = CgGrid::depth(-1.0, 2.5, 4);
  f.values.resize(4);
  double x = 0.1;
  for (CgValues& v : f.values) {
    v.density = x += 1.0 / 3.0;
    v.momentum = {x, -x, 2 * x};
    v.boundary_force = {x / 7, 0, -x};
    v.kinetic_stress = Eigen::Matrix3d::Random();
    v.contact_stress = Eigen::Matrix3d::Random();
    v.boundary_stress = Eigen::Matrix3d::Random();
    v.momentum_flux = Eigen::Matrix3d::Random();
  }
  const CgFields g = cg_fields_from_json(nlohmann::json::parse(to_json(f).dump()));
  ASSERT_EQ(g.values.size(), f.values.size());
  EXPECT_EQ(g.grid.n[2], 4);
  EXPECT_EQ(g.grid.hi[2], 2.5);
  for (std::size_t k = 0; k < f.values.size(); ++k) {
    EXPECT_EQ(g.values[k].density, f.values[k].density);
    EXPECT_EQ(g.values[k].momentum.z, f.values[k].momentum.z);
    EXPECT_EQ(g.values[k].boundary_force.x, f.values[k].boundary_force.x);
    EXPECT_EQ(g.values[k].contact_stress, f.values[k].contact_stress);
    EXPECT_EQ(g.values[k].momentum_flux, f.values[k].momentum_flux);
  }
  // A restored average continues as if never interrupted.
  CgTimeAverage a;
  a.add(f);
  a.add(g);
  CgTimeAverage b = CgTimeAverage::from_sum(cg_fields_from_json(to_json(a.sum())), a.count());
  a.add(f);
  b.add(f);
  EXPECT_EQ(a.mean().values[2].density, b.mean().values[2].density);
  EXPECT_THROW(cg_fields_from_json(nlohmann::json::object()), std::invalid_argument);
}

}  // namespace
}  // namespace talus
