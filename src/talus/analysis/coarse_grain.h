#pragma once
// Coarse graining of one snapshot into continuum fields (Weinhart et al. 2012, Sect. 3):
// density (Eq. 13), momentum (Eq. 16), velocity (Eq. 17) and stress (Eq. 32) of the flowing
// (non-fixed) particles. Contacts between flowing particles spread f_ij (x) r_ij along the line
// between the centres; a contact with a fixed particle or a wall spreads f (x) (r_i - c) along
// the line from the flowing centre to the contact point c only, and the fixed side gets nothing.
// (The paper's Eq. 32 runs that line on to infinity; ending it at c keeps the stress local and
// moves the rest into the boundary force density t_b = sum f_ik W(r - c_ik), which is zero away
// from the base. Both satisfy the momentum balance exactly; see cg_fields.h.)
#include "talus/analysis/cg_fields.h"
#include "talus/analysis/cg_function.h"
#include "talus/analysis/cg_grid.h"
#include "talus/analysis/snapshot.h"

namespace talus {

// Fields on `grid`, with f.dim == grid.dim(). Averaged axes span the whole box. Each particle
// and contact is scattered only to the grid points within the cutoff (periodic images
// included), in parallel over sources with a fixed-order reduction, so the result is
// reproducible for a given thread count. Along periodic resolved axes every image within the
// cutoff contributes, so any cutoff works. Only the first `mass_sources` particle records carry
// mass and momentum; those after them (a rank's copies of its neighbours' particles, which its
// contacts reach: World::snapshot_piece) only end contact lines, so that the pieces of a
// distributed system coarse-grain to fields whose sum is the whole system's (cg_fields_sum.h).
CgFields coarse_grain(const Snapshot& snap, const CgGrid& grid, const CgFunction& f,
                      std::size_t mass_sources = static_cast<std::size_t>(-1));

// The same fields at one point by brute force over all particles and contacts (minimum image):
// the reference for the binned coarse_grain and a way to sample fields anywhere. Throws if a
// periodic resolved axis is shorter than 2c plus the longest branch (then more than one image
// would reach the point).
CgValues coarse_grain_at(const Snapshot& snap, const CgGrid& grid, const CgFunction& f,
                         const Vec3& point);

}  // namespace talus
