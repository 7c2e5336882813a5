#pragma once
// Contact statistics of a column before the gate opens: coordination number, contact points on
// the ground, the side walls and the gate, in the whole column and near the gate, and the share
// of the weight the walls carry (Janssen effect). Huet et al. 2021, Sec. V A and Appendix E, Table III.
#include <limits>
#include <vector>

#include "talus/analysis/snapshot.h"

namespace talus::collapse {

// Which wall indices (ContactRecord::wall) play which part. A wall in no list is ignored.
struct WallRoles {
  std::vector<int> ground;
  std::vector<int> side;   ///< the two walls at y = 0 and y = W
  std::vector<int> gate;   ///< the gate at x = L0 (and the back wall, if the caller wishes)
};

// An axis-aligned box of space; infinite by default.
struct Region {
  Vec3 min{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
           -std::numeric_limits<double>::infinity()};   ///< m
  Vec3 max{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
           std::numeric_limits<double>::infinity()};    ///< m
  bool contains(const Vec3& p) const;
};

// The three columns of Table III: the whole space, the half close to the gate (x > L0/2) and the
// quarter close to the top of the gate (x > L0/2 and z > H0/2).
struct TableThreeRegions {
  Region whole, near_gate, near_gate_top;
};
TableThreeRegions table_three_regions(double initial_length, double initial_height);

// Particles belong to a region by their centre, wall contacts by their contact point.
struct ContactStatistics {
  int particles = 0;             ///< mobile particles in the region
  int neighbours = 0;            ///< sum over them of distinct contacting particles
  int contact_points = 0;        ///< sum over them of particle-particle contact points
  double coordination = 0;       ///< neighbours / particles: a pair touching at several points counts once
  double coordination_points = 0;///< contact_points / particles: every contact point counts. This is
                                 ///< the paper's 2 x contacts / N (Sec. IV C, 16.5 for crosses)
  int ground = 0;                ///< wall contact points on ground walls, in the region
  int side = 0;                  ///< on side walls
  int gate = 0;                  ///< on the gate
};

// Assumes each contact point is listed once (as i-j, not also as j-i).
ContactStatistics contact_statistics(const Snapshot& snapshot, const WallRoles& roles,
                                     const Region& region = {});

// Share of the weight of the mobile particles held up by each group of walls: the sum over its
// contacts of the force component against gravity, over sum m |g|. Huet et al. 2021, Appendix E
// (the side walls carry < 0.3 % for crosses).
struct WallLoadShares {
  double ground = 0;
  double side = 0;
  double gate = 0;
};
WallLoadShares wall_load_shares(const Snapshot& snapshot, const WallRoles& roles);

}  // namespace talus::collapse
