#pragma once
// ParaView output of the contact network: one VTK_LINE cell per ContactRecord, in the order
// of Snapshot::contacts (cell k is contact k), each line with its own two points.
//   particle-particle : from the centre of i to the centre of j; when the contact crosses a
//                       periodic boundary (centres more than half the box apart along a
//                       periodic axis), to the image of j nearest to i instead, so the line
//                       has its true length and sticks out of the box by less than a branch
//                       vector rather than spanning it ("periodic" = 1 marks those);
//   particle-wall     : from the centre of i to the contact point.
// Cell data: force (N, on i, Float64 x3), normal (unit, from j or the wall towards i),
// normal_force (N, force . normal: > 0 repulsive, < 0 adhesive), tangential_force (N,
// magnitude of the rest), overlap (m), i, j (the particles' ids; j = -1 and wall = the wall
// index for a wall contact, else wall = -1) (Int32), periodic (UInt8).
// Tube filter + colour by normal_force gives the usual force-chain picture.
#include <filesystem>

#include "talus/analysis/snapshot.h"
#include "talus/io/vtk_xml.h"

namespace talus::io {

void write_contacts_vtu(const std::filesystem::path& path, const Snapshot& snapshot);
VtuGrid contacts_grid(const Snapshot& snapshot);  ///< the grid behind the file

}  // namespace talus::io
