#pragma once
// Coarse-graining functions W: how one particle's mass, momentum or contact force is spread
// into a continuum field (Weinhart et al. 2012, Sect. 3.2.1). W acts only on the resolved
// coordinates of a field (z for a depth profile); the averaged directions are integrated out
// analytically, so a depth profile uses the 1D function and divides by the averaged area.
// Every function here is normalised so that its integral over the resolved space is exactly 1
// *with* the cutoff, so mass and the contact virial are conserved to round-off.
#include "talus/math/vec3.h"

namespace talus {

enum class CgKernel {
  gaussian,  ///< exp(-r^2 / 2w^2), cut at r = c (Weinhart et al. 2012, Eq. 14, renormalised)
  lucy,      ///< (1 + 3r/c)(1 - r/c)^3, compact in r < c (Lucy 1977; C2 at r = 0 and r = c)
};

struct CgFunction {
  CgKernel kernel = CgKernel::gaussian;
  int dim = 3;          ///< number of resolved directions, 1..3
  double width = 0;     ///< m, w: Gaussian standard deviation (for Lucy the cutoff c)
  double cutoff = 0;    ///< m, c: W = 0 for r >= c
  double norm = 0;      ///< 1/m^dim, prefactor making the integral over r < c equal to 1

  // Gaussian of width w cut at c (default 3w, where W has fallen to 1 % of its peak).
  static CgFunction gaussian(double w, int dim, double c = 0);
  // Lucy polynomial with support radius c. In 1D its standard deviation is c sqrt(2/21), so
  // c = 3.24 w resolves like a Gaussian of width w.
  static CgFunction lucy(double c, int dim);

  // W at squared distance r2 (m^2) in the resolved space.
  double value(double r2) const;
};

// ∫_0^1 W(a + s b) ds: the line integral of the contact stress (Weinhart et al. 2012, Eqs. 26
// and 32). a, b are in the resolved space (unresolved components must be zero). The segment
// is clipped to the ball r < c first, so the integrand is smooth. Exact in any dimension:
// erf for the Gaussian, a polynomial-plus-asinh antiderivative for Lucy. Segments shorter
// than 1e-2 w (Gaussian) or 1e-2 c (Lucy) use 8-point Gauss-Legendre instead, to avoid
// cancellation; that is accurate to ~1e-15 of the peak of W there.
double cg_line_integral(const CgFunction& f, const Vec3& a, const Vec3& b);

// The same integral by n-point Gauss-Legendre on each side of the point closest to the origin
// (clipped chord), for any kernel: the check of the closed forms. For the Gaussian, n = 16
// reaches 1e-10 of the peak; for Lucy off the axis convergence is slower (8e-10 at n = 16,
// 3e-11 at n = 24, from the r^3 term), in 1D it is exact from n = 3.
double cg_line_integral_quadrature(const CgFunction& f, const Vec3& a, const Vec3& b, int n);

}  // namespace talus
