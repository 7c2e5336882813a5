#pragma once
// A batch of touching sphere pairs, and the elastic-spring contact law (Weinhart et al. 2012)
// evaluated on a whole batch at once, one contact per vector lane. The lanes are laid out as
// separate arrays (one per component) so that the compiler's vector loop reads them directly;
// the law itself is the one of contact_law.h, line for line.
#include <cstdint>

#include "talus/contact/contact_table.h"
#include "talus/math/vec3.h"

namespace talus {

struct ContactBatch {
  static constexpr std::uint32_t kSize = 64;  ///< contacts; the batch and its lanes fit in L1
  std::uint32_t count = 0;
  std::uint32_t entry[kSize], i[kSize], j[kSize];
  // Results of the vector law: force on i, torques on i and j.
  alignas(64) double fx[kSize], fy[kSize], fz[kSize];
  alignas(64) double tix[kSize], tiy[kSize], tiz[kSize];
  alignas(64) double tjx[kSize], tjy[kSize], tjz[kSize];

  Vec3 force_on_i(std::uint32_t k) const { return {fx[k], fy[k], fz[k]}; }
  Vec3 torque_i(std::uint32_t k) const { return {tix[k], tiy[k], tiz[k]}; }
  Vec3 torque_j(std::uint32_t k) const { return {tjx[k], tjy[k], tjz[k]}; }
};

// Which vector batch a world's sphere pairs can take: none (contact by contact), the linear
// springs, or springs grown with the contact radius (Hertz, Mindlin). The batch needs one
// normal law for every pair (linear or Hertz), and one clamp, dashpot scaling and tangential
// stiffness law, which it then reads from any pair.
enum class BatchLaw : std::uint8_t { none, linear, grown };
BatchLaw batch_law(const ContactTable& table);

// The elastic-spring law without rolling resistance on every contact of `batch` (pairs whose
// centres are closer than r_i + r_j): fills its results and advances each contact's spring
// (Weinhart et al. 2012, Eqs. 3, 7, 9 and Alg. 2; contact_law.h has the scalar form). kGrown:
// the coefficients grow with the contact radius (BatchLaw::grown).
template <bool kGrown>
void sphere_elastic_batch(ContactBatch& batch, const Vec3* __restrict position, const Vec3* __restrict velocity,
                          const Vec3* __restrict spin, const double* __restrict radius,
                          const double* __restrict inv_mass,
                          const std::int32_t* __restrict species, const ContactTable& table,
                          Vec3* __restrict spring, double dt);

}  // namespace talus
