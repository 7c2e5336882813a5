// Coarse-grained fields of small synthetic snapshots with known answers: uniform lattice
// density, the two-particle stress of Weinhart et al. 2012 Fig. 1, the contact virial, the
// boundary stress, the kinetic stress, and the binned grid against brute force.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "talus/analysis/cg_quadrature.h"
#include "talus/analysis/coarse_grain.h"
#include "test_coarse_grain_scenes.h"

namespace talus {
namespace {

using cg_test::contact;
using cg_test::particle;

double worst_density_error(const CgFields& fields, double expect) {
  double worst = 0;
  for (const CgValues& v : fields.values) worst = std::max(worst, std::abs(v.density / expect - 1));
  return worst;
}

// (a) Uniform simple-cubic lattice: rho = N m / V in the bulk, for w >= the spacing a. The
// 1e-3 needs a cutoff of 4w for the Gaussian: cut at 3w, W jumps by 1.1 % of its peak at the
// cutoff, and lattice points crossing it give a ripple of 0.6 % (1D) to 1.4 % (3D) at w = a,
// bounded below at 2 % here. Lucy, continuous at its cutoff, needs c >= 5a (w = 1.5a).
TEST(CoarseGrainFields, LatticeDensityIsUniformInTheBulk) {
  const double a = 1, m = 2.5;
  const Snapshot s = cg_test::cubic_lattice(10, 10, 20, a, m, false);
  const double expect = m / (a * a * a);
  // Bulk: more than c + a/2 from the free top and bottom (z in [0, 20]).
  const CgGrid vol = CgGrid::volume({0, 0, 7}, {9.5, 9.5, 13}, 20, 20, 25);
  const CgGrid prof = CgGrid::depth(7, 13, 241);
  for (double w : {1.0, 1.5}) {
    EXPECT_LT(worst_density_error(coarse_grain(s, vol, CgFunction::gaussian(w, 3, 4 * w)), expect), 1e-3) << w;
    EXPECT_LT(worst_density_error(coarse_grain(s, prof, CgFunction::gaussian(w, 1, 4 * w)), expect), 1e-3) << w;
    EXPECT_LT(worst_density_error(coarse_grain(s, vol, CgFunction::gaussian(w, 3)), expect), 2e-2) << w;
    EXPECT_LT(worst_density_error(coarse_grain(s, prof, CgFunction::gaussian(w, 1)), expect), 1e-2) << w;
  }
  EXPECT_LT(worst_density_error(coarse_grain(s, vol, CgFunction::lucy(5 * a, 3)), expect), 1e-3);
  EXPECT_LT(worst_density_error(coarse_grain(s, prof, CgFunction::lucy(5 * a, 1)), expect), 1e-3);
}

// Two unit masses at z = -1 and z = +1 in a unit-area periodic column, pushed apart by |f| = 1
// (the top panel of Fig. 1, w = 0.2).
Snapshot fig1_pair(bool lower_fixed) {
  Snapshot s;
  s.domain_min = {0, 0, -3};
  s.domain_max = {1, 1, 3};
  s.periodic[0] = s.periodic[1] = true;
  s.particles = {particle({0.5, 0.5, 1}), particle({0.5, 0.5, -1}, 1, 0.5, lower_fixed)};
  s.contacts = {contact(0, 1, {0.5, 0.5, 0}, {0, 0, 1})};
  return s;
}

// ∫_{-c}^{x} W(u) du for the cut 1D Gaussian: the closed form the profiles are checked against.
double cut_cdf(const CgFunction& f, double x) {
  x = std::clamp(x, -f.cutoff, f.cutoff);
  const double k = 1 / (std::sqrt(2.0) * f.width);
  return f.norm * f.width * std::sqrt(M_PI / 2) * (std::erf(x * k) + std::erf(f.cutoff * k));
}

TEST(CoarseGrainFields, TwoFlowingParticlesGiveFigureOneProfile) {
  const CgFunction f = CgFunction::gaussian(0.2, 1);
  const CgFields prof = coarse_grain(fig1_pair(false), CgGrid::depth(-2, 2, 401), f);
  for (int k = 0; k < prof.grid.size(); ++k) {
    const double z = prof.grid.point(k).z;
    const CgValues& v = prof.values[k];
    EXPECT_NEAR(v.density, f.value((z - 1) * (z - 1)) + f.value((z + 1) * (z + 1)), 1e-13);
    // f_z r_z ∫_0^1 W(z - 1 + 2s) ds = ∫_{-1}^{1} W(z - u) du: 1 between the centres, a
    // smoothed step at each centre, nothing outside.
    EXPECT_NEAR(v.contact_stress(2, 2), cut_cdf(f, z + 1) - cut_cdf(f, z - 1), 1e-13) << z;
    if (std::abs(z) < 1 - f.cutoff) EXPECT_NEAR(v.contact_stress(2, 2), 1, 1e-13);
    EXPECT_EQ(v.boundary_stress.norm(), 0);
  }
}

// ∫ field dz over the whole profile by 32-point Gauss-Legendre between the kinks of the cut
// functions (breaks), sampling the field by brute force.
template <class Get>
Eigen::Matrix3d integrate_z(const Snapshot& s, const CgFunction& f, std::vector<double> breaks, Get get) {
  std::sort(breaks.begin(), breaks.end());
  const CgGrid axis = CgGrid::depth(0, 0, 1);  // only says "resolve z"
  const GaussLegendreRule& rule = gauss_legendre(32);
  Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
  for (std::size_t p = 0; p + 1 < breaks.size(); ++p) {
    const double mid = 0.5 * (breaks[p] + breaks[p + 1]), half = 0.5 * (breaks[p + 1] - breaks[p]);
    for (std::size_t k = 0; k < rule.nodes.size(); ++k)
      sum += half * rule.weights[k] * get(coarse_grain_at(s, axis, f, {0, 0, mid + half * rule.nodes[k]}));
  }
  return sum;
}

Eigen::Matrix3d outer(const Vec3& a, const Vec3& b) {
  return Eigen::Vector3d(a.x, a.y, a.z) * Eigen::Vector3d(b.x, b.y, b.z).transpose();
}

// (b) Integrated over space, the contact stress of one contact is its virial f (x) r_ij, for a
// branch that crosses the periodic x-y boundary (minimum image).
TEST(CoarseGrainFields, ContactStressIntegratesToTheVirial) {
  Snapshot s;
  s.domain_min = {0, 0, -4};
  s.domain_max = {1.5, 2, 4};
  s.periodic[0] = s.periodic[1] = true;
  s.particles = {particle({1.4, 0.1, 1.2}), particle({0.2, 1.8, -0.7})};
  const Vec3 force{0.3, -0.4, 1.1};
  s.contacts = {contact(0, 1, {0, 0, 0}, force)};
  const Vec3 branch{-0.3, 0.3, 1.9};  // r_0 - r_1 by minimum image
  const double area = 1.5 * 2;
  for (const CgFunction& f : {CgFunction::gaussian(0.3, 1), CgFunction::lucy(0.8, 1)}) {
    const double c = f.cutoff;
    const Eigen::Matrix3d total = area * integrate_z(s, f, {-4, 1.2 - c, 1.2, 1.2 + c, -0.7 - c, -0.7, -0.7 + c, 4},
                                                     [](const CgValues& v) { return v.contact_stress; });
    EXPECT_LT((total - outer(force, branch)).cwiseAbs().maxCoeff(), 1e-10) << total;
  }
}

// (b) A flowing particle on a fixed one (or a wall): its stress runs from its centre to the
// contact point only and integrates to f (x) (r_i - c); the fixed side gets nothing.
TEST(CoarseGrainFields, BoundaryStressEndsAtTheContactPoint) {
  const CgFunction f = CgFunction::gaussian(0.2, 1);
  const Vec3 force{0.2, 0, 1}, point{0.5, 0.5, 0}, centre{0.7, 0.4, 1};
  for (int variant = 0; variant < 3; ++variant) {
    Snapshot s;
    s.domain_min = {0, 0, -3};
    s.domain_max = {1, 1, 3};
    s.periodic[0] = s.periodic[1] = true;
    s.particles = {particle(centre), particle({0.5, 0.5, -1}, 1, 1, true)};
    if (variant == 0) s.contacts = {contact(0, 1, point, force)};
    if (variant == 1) s.contacts = {contact(1, 0, point, -force)};  // listed from the fixed side
    if (variant == 2) s.contacts = {contact(0, -1, point, force)};  // a wall
    const std::vector<double> breaks{-3, -f.cutoff, 0, f.cutoff, 1 - f.cutoff, 1, 1 + f.cutoff, 3};
    const Eigen::Matrix3d total =
        integrate_z(s, f, breaks, [](const CgValues& v) { return v.boundary_stress; });
    EXPECT_LT((total - outer(force, centre - point)).cwiseAbs().maxCoeff(), 1e-10) << variant;
    const Eigen::Matrix3d base = integrate_z(s, f, breaks, [](const CgValues& v) {
      return Eigen::Matrix3d(Eigen::Vector3d(v.boundary_force.x, v.boundary_force.y, v.boundary_force.z).asDiagonal());
    });
    EXPECT_NEAR(base(0, 0), force.x, 1e-10);
    EXPECT_NEAR(base(2, 2), force.z, 1e-10);
    // Nothing below the contact point's reach (the fixed particle at z = -1 carries no stress).
    const CgFields prof = coarse_grain(s, CgGrid::depth(-2, 2, 81), f);
    for (int k = 0; k < prof.grid.size(); ++k) {
      const double z = prof.grid.point(k).z;
      if (z < -f.cutoff) {
        EXPECT_EQ(prof.values[k].boundary_stress.norm(), 0) << z;
        EXPECT_EQ(prof.values[k].density, 0) << z;
      }
      EXPECT_EQ(prof.values[k].contact_stress.norm(), 0);
    }
  }
}

// Eqs. 29-30: fluctuations are taken about the coarse-grained velocity at the field point.
TEST(CoarseGrainFields, KineticStressUsesFluctuationsAboutTheLocalVelocity) {
  Snapshot s;
  s.domain_min = {0, 0, -2};
  s.domain_max = {1, 1, 2};
  s.particles = {particle({0.5, 0.5, 0.1}, 2), particle({0.5, 0.5, 0.1}, 2)};
  s.particles[0].velocity = {1.5, 0, 0.2};
  s.particles[1].velocity = {0.5, 0, -0.2};
  const CgFunction f = CgFunction::gaussian(0.3, 1);
  const CgValues v = coarse_grain_at(s, CgGrid::depth(0, 0, 1), f, {0, 0, 0.3});
  const double w = f.value(0.04);
  EXPECT_NEAR(v.density, 4 * w, 1e-14);
  EXPECT_NEAR(v.velocity().x, 1, 1e-14);
  EXPECT_NEAR(v.kinetic_stress(0, 0), 2 * 2 * 0.25 * w, 1e-13);
  EXPECT_NEAR(v.kinetic_stress(0, 2), 2 * 2 * 0.5 * 0.2 * w, 1e-13);
  EXPECT_NEAR(v.kinetic_stress(2, 2), 2 * 2 * 0.04 * w, 1e-13);
  EXPECT_NEAR(v.momentum_flux(0, 0), 2 * (2.25 + 0.25) * w, 1e-13);
}

// The binned, parallel grid path against brute force at every point, for 1D, 2D and 3D grids
// and both kernels, on a packing with periodic contacts and wall contacts.
TEST(CoarseGrainFields, GridMatchesBruteForce) {
  const Snapshot s = cg_test::jittered_packing(6, 5, 6, 1.0, 11);
  struct Case { CgGrid grid; CgFunction f; };
  const Case cases[] = {
      {CgGrid::depth(-0.5, 6.5, 71), CgFunction::gaussian(0.4, 1)},
      {CgGrid::depth(-0.5, 6.5, 71), CgFunction::lucy(1.2, 1)},
      {CgGrid::plane(0, 0, 6, 13, 2, -0.5, 6.5, 15), CgFunction::gaussian(0.5, 2)},
      {CgGrid::volume({0, 0, 0}, {6, 5, 6}, 7, 6, 8), CgFunction::gaussian(0.5, 3)},
      {CgGrid::volume({0, 0, 0}, {6, 5, 6}, 7, 6, 8), CgFunction::lucy(1.5, 3)},
  };
  for (const Case& cs : cases) {
    const CgFields grid = coarse_grain(s, cs.grid, cs.f);
    double scale = 0, worst = 0;
    for (int k = 0; k < cs.grid.size(); ++k) {
      const CgValues ref = coarse_grain_at(s, cs.grid, cs.f, cs.grid.point(k));
      const CgValues& v = grid.values[k];
      scale = std::max({scale, ref.density, ref.stress().norm()});
      worst = std::max({worst, std::abs(v.density - ref.density), norm(v.momentum - ref.momentum),
                        (v.kinetic_stress - ref.kinetic_stress).norm(), (v.contact_stress - ref.contact_stress).norm(),
                        (v.boundary_stress - ref.boundary_stress).norm(), norm(v.boundary_force - ref.boundary_force)});
    }
    EXPECT_GT(scale, 0);
    EXPECT_LT(worst, 1e-12 * scale) << "dim " << cs.f.dim;
  }
}

}  // namespace
}  // namespace talus
