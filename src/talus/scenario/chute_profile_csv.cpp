#include "talus/scenario/chute_profile_csv.h"

#include <string>
#include <vector>

#include "talus/analysis/cg_balance.h"
#include "talus/analysis/depth_profile.h"
#include "talus/io/csv_writer.h"

namespace talus {

void write_chute_profile_csv(const std::filesystem::path& path, const CgFields& profile, const Vec3& gravity,
                             double particle_density) {
  static const char* axis = "xyz";
  std::vector<std::string> cols = {"z", "density", "volume_fraction", "velocity_x", "velocity_y", "velocity_z"};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) cols.push_back(std::string("stress_") + axis[r] + axis[c]);
  for (const char* part : {"kinetic", "contact", "boundary"})
    for (const char* comp : {"xx", "yy", "zz", "xz"}) cols.push_back(std::string(part) + "_" + comp);
  for (const char* c : {"stress_xz_planes", "stress_zz_planes", "lithostatic_zz", "mass_residual",
                        "momentum_residual_x", "momentum_residual_y", "momentum_residual_z"})
    cols.push_back(c);

  const std::vector<double> z = profile_z(profile);
  const std::vector<double> sxz = profile_stress_on_planes(profile, 0), szz = profile_stress_on_planes(profile, 2);
  std::vector<double> weight(z.size());
  for (std::size_t k = 0; k < z.size(); ++k) weight[k] = -profile.values[k].density * gravity.z;
  const BalanceResiduals res = steady_balance(profile, gravity);

  io::CsvWriter csv(path, cols);
  std::vector<double> row;
  for (std::size_t k = 0; k < z.size(); ++k) {
    const CgValues& v = profile.values[k];
    const Vec3 u = v.velocity();
    const Eigen::Matrix3d s = v.stress();
    row = {z[k], v.density, v.density / particle_density, u.x, u.y, u.z};
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) row.push_back(s(r, c));
    for (const Eigen::Matrix3d* m : {&v.kinetic_stress, &v.contact_stress, &v.boundary_stress})
      row.insert(row.end(), {(*m)(0, 0), (*m)(1, 1), (*m)(2, 2), (*m)(0, 2)});
    // Weinhart et al. 2012, Eq. (41): the weight of the flow above z.
    const double litho = integrate_profile(z, weight, z[k], z.back());
    row.insert(row.end(), {sxz[k], szz[k], litho, res.mass[k], res.momentum[k].x, res.momentum[k].y, res.momentum[k].z});
    csv.row(std::span<const double>(row));
  }
  csv.close();
}

}  // namespace talus
