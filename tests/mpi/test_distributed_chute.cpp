// A chute spread over the ranks against the same chute on one rank.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <random>

#include "talus/analysis/cg_fields_sum.h"
#include "talus/analysis/coarse_grain.h"
#include "talus/parallel/communicator.h"
#include "talus/scenario/chute.h"

namespace talus {
namespace {

struct Body {
  std::uint32_t gid;
  Vec3 position, velocity, angular_velocity;
};

// Every rank's owned particles, by global id, on every rank.
std::map<std::uint32_t, Body> gather(const World& w) {
  const ParticleStore& p = w.particles();
  std::vector<std::byte> mine;
  ByteWriter out(mine);
  for (std::size_t i = 0; i < p.owned; ++i) out.put(Body{p.gid[i], p.position[i], p.velocity[i], p.angular_velocity[i]});
  const std::vector<std::byte> all = w.communicator().all_gather(mine);
  std::map<std::uint32_t, Body> bodies;
  ByteReader in(all);
  while (!in.done()) {
    const Body b = in.get<Body>();
    EXPECT_TRUE(bodies.emplace(b.gid, b).second) << "particle " << b.gid << " owned by two ranks";
  }
  return bodies;
}

ChuteSetup small_chute() {
  ChuteSetup s;
  s.length = 20;
  s.width = 8;
  s.fill_height = 4;
  s.angle_deg = 26;  // above h_stop at this depth: the layer flows, springs stay loaded
  s.flow = s.base = weinhart_chute_contact();
  return s;
}

// A small chute of Weinhart et al. 2012, Sect. 5 (d = 1, m = 1, g = 1), built fast: a base of
// fixed spheres on a jittered square lattice, flowing spheres on a cubic lattice just wider than
// touching with random velocities, so that contacts form within a few hundred steps.
// `base_layers` layers of fixed spheres make the base, the top one rough.
std::unique_ptr<World> lattice_chute(std::uint64_t seed = 7, int base_layers = 1) {
  const ChuteSetup s = small_chute();
  auto world = make_chute_world(s);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.05, 0.05);
  for (int k = base_layers - 1; k >= 0; --k)
    for (int i = 0; i < static_cast<int>(s.length); ++i)
      for (int j = 0; j < static_cast<int>(s.width); ++j)
        world->add_sphere({i + 0.5, j + 0.5, k == 0 ? jitter(rng) : -1.0 * k}, 0.5, s.density, 1, true);
  for (int k = 0; k < static_cast<int>(s.fill_height); ++k)
    for (int i = 0; i < static_cast<int>(s.length / 1.02); ++i)
      for (int j = 0; j < static_cast<int>(s.width / 1.02); ++j) {
        ParticleInit p;
        p.position = {0.3 + 1.02 * i, 0.3 + 1.02 * j, 1.1 + 1.02 * k};
        p.velocity = {2 * jitter(rng), 2 * jitter(rng), 2 * jitter(rng)};
        p.radius = 0.5 * (1 + jitter(rng) * 0.2);  // 1 % polydispersity
        p.mass = s.density * 4.0 / 3.0 * std::numbers::pi * p.radius * p.radius * p.radius;
        const double inertia = 0.4 * p.mass * p.radius * p.radius;
        p.inertia = {inertia, inertia, inertia};
        world->add_particle(p);
      }
  return world;
}

// Largest difference over all particles, in units of the diameter (positions, minimum image)
// and of sqrt(g d) (velocities).
struct Difference {
  double position = 0, velocity = 0, angular_velocity = 0;
};

Difference compare(const World& reference, const std::map<std::uint32_t, Body>& bodies) {
  const ParticleStore& p = reference.particles();
  Difference d;
  EXPECT_EQ(bodies.size(), p.owned);
  for (std::size_t i = 0; i < p.owned; ++i) {
    const auto it = bodies.find(p.gid[i]);
    if (it == bodies.end()) {
      ADD_FAILURE() << "particle " << p.gid[i] << " lost";
      continue;
    }
    const Vec3 dx = reference.settings().domain.minimum_image(it->second.position - p.position[i]);
    d.position = std::max(d.position, norm(dx));
    d.velocity = std::max(d.velocity, norm(it->second.velocity - p.velocity[i]));
    d.angular_velocity = std::max(d.angular_velocity, norm(it->second.angular_velocity - p.angular_velocity[i]));
  }
  return d;
}

TEST(DistributedChute, SameTrajectoriesToRoundOffOverTheFirstHundredSteps) {
  const Communicator& comm = Communicator::world();
  // Both worlds flow alike for 2,000 steps first, so that the cuts go through contacts whose
  // tangential springs are loaded; then one is spread over the ranks.
  auto reference = lattice_chute();
  auto spread = lattice_chute();
  reference->run(2000);
  spread->run(2000);
  ASSERT_GT(reference->diagnostics().elastic_tangential, 0);
  spread->distribute(comm);
  const RankCounts n = spread->rank_grid().counts();
  EXPECT_EQ(n[0] * n[1] * n[2], comm.size());
  reference->run(100);
  spread->run(100);
  const Difference d = compare(*reference, gather(*spread));
  // Sums over a particle's contacts are added in another order on another rank layout, so the
  // forces differ in their last bits (1e-16 relative); a dense flow amplifies that by a few
  // orders over 100 steps (two contact times), far below any physical scale.
  EXPECT_LT(d.position, 1e-10);
  EXPECT_LT(d.velocity, 1e-8);
  EXPECT_LT(d.angular_velocity, 1e-8);
  // Energy bookkeeping agrees as well: the elastic energy of springs across cuts is counted once.
  const Diagnostics a = reference->diagnostics(), b = spread->diagnostics();
  EXPECT_NEAR(b.kinetic(), a.kinetic(), 1e-9 * a.kinetic());
  EXPECT_NEAR(b.elastic_tangential, a.elastic_tangential, 1e-6 * a.elastic_tangential);
  EXPECT_EQ(b.contacts, a.contacts);
  // The snapshot joins the ranks' pieces: every particle once, every contact once, with the
  // force it carries on one rank.
  const Snapshot one = reference->snapshot(), all = spread->snapshot();
  ASSERT_EQ(all.particles.size(), one.particles.size());
  for (std::size_t k = 0; k < one.particles.size(); ++k) ASSERT_EQ(all.particles[k].id, one.particles[k].id);
  ASSERT_EQ(all.contacts.size(), one.contacts.size());
  std::map<std::pair<int, int>, Vec3> force;
  for (const ContactRecord& c : one.contacts) force[{std::min(c.i, c.j), std::max(c.i, c.j)}] = c.i < c.j ? c.force : -1.0 * c.force;
  for (const ContactRecord& c : all.contacts) {
    const auto it = force.find({std::min(c.i, c.j), std::max(c.i, c.j)});
    ASSERT_NE(it, force.end());
    EXPECT_LT(norm((c.i < c.j ? c.force : -1.0 * c.force) - it->second), 1e-9 * (1 + norm(it->second)));
  }
}

// Pairs this rank lists with a ghost from the rank above whose memory holds a loaded spring.
double springs_across_cuts(const World& w) {
  const PairList& list = w.pair_list();
  double n = 0;
  for (std::size_t i = 0; i < list.rows(); ++i)
    for (std::uint32_t e = list.row_begin(i); e < list.row_end(i); ++e)
      n += list.neighbor(e) >= w.halo().first() && norm2(list.memory.spring[e]) > 0;
  return w.communicator().sum(n);
}

TEST(DistributedChute, ParticlesCrossCutsAndThePeriodicFaceWithTheirSprings) {
  // From the lattice on: the layer collapses, then flows down the slope (along x, the slab
  // axis), across the cuts and the periodic face, for 5,000 steps (100 contact times).
  const Communicator& comm = Communicator::world();
  auto reference = lattice_chute();
  auto spread = lattice_chute();
  spread->distribute(comm);
  if (comm.size() > 1) EXPECT_GT(spread->rank_grid().counts()[0], 1);  // the slope is cut
  double crossed = 0;
  for (int k = 0; k < 5; ++k) {
    reference->run(1000);
    spread->run(1000);
    crossed = comm.sum(static_cast<double>(spread->particles_moved_between_ranks()));
  }
  if (comm.size() > 1) {
    EXPECT_GT(crossed, 0);
    EXPECT_GT(springs_across_cuts(*spread), 0);
  }
  // The same trajectories: any difference is round-off grown by the flow's chaos, which
  // measured stays below 1e-15 d here (and 1e-10 d after 20,000 steps).
  const Difference d = compare(*reference, gather(*spread));
  EXPECT_LT(d.position, 1e-10);
  EXPECT_LT(d.velocity, 1e-8);
}

// Each rank coarse-grains its piece (its particles, and the contacts it lists with their
// partners' copies); the sum over ranks is the whole system's fields, on a depth profile and on
// a volume grid whose points lie across the cuts and the periodic faces, after the flow has
// carried particles and loaded springs across them.
TEST(DistributedChute, CoarseGrainedPiecesAddUpToTheWholeSystem) {
  const Communicator& comm = Communicator::world();
  auto spread = lattice_chute();
  spread->distribute(comm);
  spread->run(5000);
  if (comm.size() > 1) ASSERT_GT(springs_across_cuts(*spread), 0);
  if (comm.size() > 1) ASSERT_GT(comm.sum(static_cast<double>(spread->particles_moved_between_ranks())), 0);
  const Snapshot whole = spread->snapshot();
  const World::SnapshotPiece piece = spread->snapshot_piece();
  const ChuteSetup s = small_chute();
  for (const CgGrid& grid : {CgGrid::depth(-1, 6, 36), CgGrid::volume({0, 0, -1}, {s.length, s.width, 6}, 10, 4, 8)}) {
    const CgFunction f = CgFunction::gaussian(0.5, grid.dim());
    const CgFields expected = coarse_grain(whole, grid, f);
    CgFields summed = coarse_grain(piece.snapshot, grid, f, piece.owned);
    sum_over_ranks(summed, comm);
    ASSERT_EQ(summed.values.size(), expected.values.size());
    double scale_rho = 0, scale_stress = 0;
    for (const CgValues& v : expected.values) {
      scale_rho = std::max(scale_rho, v.density);
      scale_stress = std::max(scale_stress, v.contact_stress.norm() + v.boundary_stress.norm());
    }
    ASSERT_GT(scale_stress, 0);
    // The same sums in another order: round-off, 1e-12 of the largest value.
    for (std::size_t k = 0; k < expected.values.size(); ++k) {
      const CgValues &a = expected.values[k], &b = summed.values[k];
      EXPECT_NEAR(b.density, a.density, 1e-12 * scale_rho) << "point " << k;
      EXPECT_LT(norm(b.momentum - a.momentum), 1e-12 * scale_rho * (1 + norm(a.velocity())));
      EXPECT_LT((b.contact_stress - a.contact_stress).norm(), 1e-12 * scale_stress) << "point " << k;
      EXPECT_LT((b.boundary_stress - a.boundary_stress).norm(), 1e-12 * scale_stress) << "point " << k;
      EXPECT_LT((b.kinetic_stress - a.kinetic_stress).norm(), 1e-10 * scale_stress) << "point " << k;
      EXPECT_LT(norm(b.boundary_force - a.boundary_force), 1e-12 * (1 + norm(a.boundary_force)) * scale_rho);
    }
  }
}

// Every grid of the ranks (4 ranks: 4 x 1 x 1, 2 x 2 x 1, 1 x 2 x 2, ...), with each of its cut
// axes as the pair list's slab axis, follows the same trajectories from the lattice on, as it
// collapses into a flow across all cuts, their edges and the periodic faces.
TEST(DistributedChute, EveryGridOfRanksSameAsOneRank) {
  const Communicator& comm = Communicator::world();
  auto reference = lattice_chute();
  reference->run(4000);
  const int n = comm.size();
  int grids = 0;
  for (int px = 1; px <= n; ++px)
    for (int py = 1; py * px <= n; ++py) {
      if (n % (px * py)) continue;
      const RankCounts counts{px, py, n / (px * py)};
      for (int slab_axis = 0; slab_axis < 3; ++slab_axis) {
        if (counts[slab_axis] == 1 && n > 1) continue;
        auto spread = lattice_chute();
        spread->distribute(comm, counts, slab_axis);
        ASSERT_EQ(spread->rank_grid().counts(), counts);
        spread->run(4000);
        const Difference d = compare(*reference, gather(*spread));
        EXPECT_LT(d.position, 1e-10) << counts[0] << " x " << counts[1] << " x " << counts[2] << ", slab axis " << slab_axis;
        EXPECT_LT(d.velocity, 1e-8);
        EXPECT_EQ(spread->diagnostics().contacts, reference->diagnostics().contacts);
        if (n > 1) EXPECT_GT(comm.sum(static_cast<double>(spread->particles_moved_between_ranks())), 0);
        ++grids;
      }
    }
  EXPECT_GE(grids, n == 4 ? 9 : n == 2 ? 3 : 1);
}

// The heaviest rank's share of the contacts' work (1 plus the pair and wall entries of each
// owned particle's rows) over the mean share.
double work_imbalance(const World& w) {
  const PairList& list = w.pair_list();
  double work = 0;
  for (std::size_t i = 0; i < w.owned_count(); ++i) work += 1 + (list.row_end(i) - list.row_begin(i));
  const Communicator& comm = w.communicator();
  return comm.max(work) / (comm.sum(work) / comm.size());
}

// A base four layers thick: slabs across the depth balanced by particle count give the rank
// holding the fixed base (whose pairs among themselves are never listed) less work than the
// others; balanced by the contacts' work (run.balance = "neighbours") the cuts move until no
// rank holds more than 1.1 times the mean (measured: 1.50 by count, 1.01 by contacts after
// 6,000 steps), and the flow is the same.
TEST(DistributedChute, CutsBalanceTheContactsWork) {
  const Communicator& comm = Communicator::world();
  if (comm.size() != 2) GTEST_SKIP() << "two slabs across the depth";
  auto reference = lattice_chute(7, 4);
  reference->run(6000);  // the layer collapses: a dozen rebuilds
  double imbalance[2];
  for (const RankGrid::Balance balance : {RankGrid::Balance::count, RankGrid::Balance::neighbours}) {
    auto spread = lattice_chute(7, 4);
    spread->distribute(comm, {1, 1, comm.size()}, 2);
    spread->balance_ranks_by(balance);
    spread->run(6000);
    const Difference d = compare(*reference, gather(*spread));
    EXPECT_LT(d.position, 1e-10);
    imbalance[balance == RankGrid::Balance::neighbours] = work_imbalance(*spread);
  }
  EXPECT_GT(imbalance[0], 1.15);
  EXPECT_LT(imbalance[1], 1.12);
  if (comm.rank() == 0) std::printf("work imbalance: %.3f by count, %.3f by contacts\n", imbalance[0], imbalance[1]);
}

TEST(DistributedChute, SlabsAcrossTheDepthWithAnEmptyRank) {
  // Slabs along z, not periodic: the base and the bottom layer, the next layer, the rest of the
  // flow, and (from four ranks on) a slab above it that no particle reaches.
  const Communicator& comm = Communicator::world();
  auto reference = lattice_chute();
  auto spread = lattice_chute();
  std::vector<double> cut{-std::numeric_limits<double>::infinity()};
  const double inner[] = {1.6, 3.2, 30.0};
  for (int r = 1; r < comm.size(); ++r) cut.push_back(r <= 3 ? inner[r - 1] : 30.0 + 2 * (r - 3));
  cut.push_back(std::numeric_limits<double>::infinity());
  spread->distribute(RankGrid::slabs(comm, spread->settings().domain, 2, cut, 1.5));
  reference->run(3000);
  spread->run(3000);
  const Difference d = compare(*reference, gather(*spread));
  EXPECT_LT(d.position, 1e-10);
  EXPECT_LT(d.velocity, 1e-8);
  const Diagnostics a = reference->diagnostics(), b = spread->diagnostics();
  EXPECT_EQ(b.contacts, a.contacts);
  if (comm.size() >= 4) {
    const double top = comm.rank() == 3 ? static_cast<double>(spread->owned_count()) : 0.0;
    EXPECT_EQ(comm.sum(top), 0);
  }
}

}  // namespace
}  // namespace talus
