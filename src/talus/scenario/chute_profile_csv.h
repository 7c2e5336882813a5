#pragma once
// A time-averaged chute depth profile as CSV (Weinhart et al. 2012, Figs. 6-8): one row per
// height with density, volume fraction, velocity, the stress tensor and its kinetic, contact and
// boundary parts, the base-extended sigma_xz and sigma_zz, the lithostatic weight (Eq. 41) and
// the residuals of the steady balances (Eqs. 18, 44). Written atomically.
#include <filesystem>

#include "talus/analysis/cg_fields.h"
#include "talus/math/vec3.h"

namespace talus {

void write_chute_profile_csv(const std::filesystem::path& path, const CgFields& profile, const Vec3& gravity,
                             double particle_density);

}  // namespace talus
