#pragma once
// The contact force network as branch-vector segments, and the contact force magnitudes it
// carries. Huet et al. 2021, Sec. IV C, Fig. 14: each segment links the centres of mass of two
// touching particles and is coloured by F_c / <F_c>.
#include <vector>

#include "talus/analysis/snapshot.h"

namespace talus {

// Nonconvex particles can touch at several points. Huet et al. 2021 (Sec. IV C 1) keep each
// point as its own, weaker branch vector; merging sums the pair's forces into one segment.
enum class PairPoints { EachPoint, MergePerPair };

struct ForceSegment {
  int i = -1, j = -1;   ///< particle indices in Snapshot::particles
  Vec3 from;            ///< m, centre of mass of i
  Vec3 to;              ///< m, centre of mass of j, as the periodic image nearest to i
  double force = 0;     ///< N, |F| of the contact point, or |sum of F| of the pair when merged
  int points = 1;       ///< contact points the segment stands for
};

// x_j - x_i, through the nearest periodic image along periodic axes of the snapshot.
Vec3 branch_vector(const Snapshot& snapshot, int i, int j);

// Particle-particle contacts only; wall contacts have no second centre.
std::vector<ForceSegment> force_network(const Snapshot& snapshot, PairPoints points = PairPoints::EachPoint);

// |F| of every particle-particle contact point (or merged pair), optionally with wall contacts.
std::vector<double> contact_force_magnitudes(const Snapshot& snapshot, PairPoints points = PairPoints::EachPoint,
                                             bool include_walls = false);

}  // namespace talus
