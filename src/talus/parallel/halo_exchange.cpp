#include "talus/parallel/halo_exchange.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace talus {

namespace {
// Message tags: the passes of creation, then the forward and the reverse exchange of each pass.
constexpr int kCreateTag = 100, kForwardTag = 120, kReverseTag = 140;

// The state of a copy between rebuilds. A sphere's orientation does not change, so a sphere's
// copy takes only its motion.
struct SphereGhostState {
  Vec3 position, velocity, angular_velocity;
};

struct GhostState {
  SphereGhostState motion;
  Quat orientation;
};

// The state a ghost takes from its original, shifted across the periodic face; its force is reset.
SphereGhostState sphere_state_of(const ParticleStore& p, std::size_t k, int axis, double shift) {
  SphereGhostState s{p.position[k], p.velocity[k], p.angular_velocity[k]};
  s.position[axis] += shift;
  return s;
}

GhostState state_of(const ParticleStore& p, std::size_t k, int axis, double shift) {
  return {sphere_state_of(p, k, axis, shift), p.orientation[k]};
}

void set_sphere_state(ParticleStore& p, std::size_t k, const SphereGhostState& s) {
  p.position[k] = s.position;
  p.velocity[k] = s.velocity;
  p.angular_velocity[k] = s.angular_velocity;
  p.force[k] = {};
  p.torque[k] = {};
}

void set_state(ParticleStore& p, std::size_t k, const GhostState& s) {
  set_sphere_state(p, k, s.motion);
  p.orientation[k] = s.orientation;
}

// One forward pass in the state type T: pack, swap with the neighbours, unpack.
template <class T, class Pack, class Unpack>
void forward_pass(const Communicator& comm, const std::vector<std::uint32_t>& sent, std::size_t first,
                  std::size_t received, int to, int from, int tag, std::vector<std::byte>& out,
                  std::vector<std::byte>& in, Pack pack, Unpack unpack) {
  out.resize(sent.size() * sizeof(T));
  for (std::size_t n = 0; n < sent.size(); ++n) {
    const T s = pack(sent[n]);
    std::memcpy(out.data() + n * sizeof(T), &s, sizeof(T));
  }
  in.resize(received * sizeof(T));
  comm.exchange_sized(out, to, from, tag, in);
  if (in.size() != received * sizeof(T)) throw std::logic_error("halo forward exchange out of step");
  for (std::size_t g = 0; g < received; ++g) {
    T s;
    std::memcpy(&s, in.data() + g * sizeof(T), sizeof(T));
    unpack(first + g, s);
  }
}

struct GhostConstants {
  double radius, inv_mass, mass;
  Vec3 inv_inertia;
  std::int32_t species, shape;
  std::uint32_t gid;
};

// The cell of a copy that came across `axis` from the side `step` (+1: from above): the ghost
// layer there. Along the slab axis a copy from a rank of the same slab lies in the layer its
// owner put it in (the grids of those ranks match along it), which decides which of the two
// lists the pair (pair_list.h); along other axes any layer next to it finds its neighbours.
CellCoord cell_across(const CellGrid& grid, const Vec3& x, int axis, int step) {
  CellCoord c;
  for (int a = 0; a < 3; ++a) {
    const double k = std::floor((x[a] - grid.origin(a)) / grid.width(a));
    const bool inside = a == grid.slab_axis();
    const int lo = inside ? 0 : grid.first(a), hi = inside ? grid.cells(a) - 1 : grid.last(a);
    c[a] = static_cast<int>(std::clamp(k, static_cast<double>(lo), static_cast<double>(hi)));
  }
  c[axis] = step > 0 ? grid.last(axis) : grid.first(axis);
  return c;
}
}  // namespace

void HaloExchange::create(ParticleStore& p, const RankGrid& ranks, const CellGrid& grid, double band,
                          std::vector<CellCoord>& cell_of, bool oriented) {
  ranks_ = &ranks;
  oriented_ = oriented;
  passes_.clear();
  int tag = kCreateTag;
  for (const int axis : ranks.stage_axes()) {
    const SlabDecomposition& slabs = ranks.axes[axis];
    const double length = slabs.periodic ? slabs.length : 0.0;
    // Down: the copies near the lower cut go to the rank below, and those from above arrive.
    Pass down{axis, ranks.neighbour(axis, -1), ranks.neighbour(axis, +1), 0,
              slabs.index == 0 ? length : 0.0, {}, 0, 0};
    Pass up{axis, ranks.neighbour(axis, +1), ranks.neighbour(axis, -1), 0,
            slabs.index + 1 == slabs.slabs() ? -length : 0.0, {}, 0, 0};
    const bool both_ways = axis != ranks.slab_axis;
    const double lo = slabs.lo(), hi = slabs.hi();
    for (std::size_t k = 0; k < p.size(); ++k) {  // everything held before this stage
      if (p.position[k][axis] - lo < band) down.sent.push_back(static_cast<std::uint32_t>(k));
      if (both_ways && hi - p.position[k][axis] < band) up.sent.push_back(static_cast<std::uint32_t>(k));
    }
    std::vector<Pass> stage;
    stage.push_back(std::move(down));
    if (both_ways) stage.push_back(std::move(up));
    for (Pass& pass : stage) {
      pass.tag = tag;
      tag += 2;
      std::vector<std::byte> out;
      ByteWriter w(out);
      w.put(static_cast<std::uint64_t>(pass.sent.size()));
      for (const std::uint32_t k : pass.sent) {
        w.put(state_of(p, k, axis, pass.shift));
        w.put(GhostConstants{p.radius[k], p.inv_mass[k], p.mass[k], p.inv_inertia[k], p.species[k], p.shape[k], p.gid[k]});
      }
      if (pass.to < 0) pass.sent.clear();  // nobody there: the copies stay unsent
      const std::vector<std::byte> in = ranks.comm->exchange(out, pass.to, pass.from, pass.tag);
      pass.first = p.size();
      pass.received = 0;
      if (!in.empty()) {
        ByteReader r(in);
        pass.received = r.get<std::uint64_t>();
        p.resize(pass.first + pass.received);
        cell_of.resize(pass.first + pass.received);
        const int step = &pass == &stage.front() ? +1 : -1;  // down's copies come from above
        for (std::size_t g = 0; g < pass.received; ++g) {
          const std::size_t k = pass.first + g;
          const auto s = r.get<GhostState>();
          const auto c = r.get<GhostConstants>();
          set_state(p, k, s);
          p.radius[k] = c.radius;
          p.inv_mass[k] = c.inv_mass;
          p.mass[k] = c.mass;
          p.inv_inertia[k] = c.inv_inertia;
          p.species[k] = c.species;
          p.shape[k] = c.shape;
          p.gid[k] = c.gid;
          cell_of[k] = cell_across(grid, s.motion.position, axis, step);
        }
      }
      passes_.push_back(std::move(pass));
    }
  }
}

std::size_t HaloExchange::count() const {
  std::size_t n = 0;
  for (const Pass& pass : passes_) n += pass.received;
  return n;
}

std::vector<std::uint32_t> HaloExchange::sent_indices() const {
  std::vector<std::uint32_t> all;
  for (const Pass& pass : passes_) all.insert(all.end(), pass.sent.begin(), pass.sent.end());
  return all;
}

// Between rebuilds both sides know the message sizes: one message each way.
void HaloExchange::forward(ParticleStore& p) const {
  for (const Pass& pass : passes_) {
    const int tag = kForwardTag + pass.tag - kCreateTag;
    if (oriented_)
      forward_pass<GhostState>(
          *ranks_->comm, pass.sent, pass.first, pass.received, pass.to, pass.from, tag, out_, in_,
          [&](std::uint32_t k) { return state_of(p, k, pass.axis, pass.shift); },
          [&](std::size_t k, const GhostState& s) { set_state(p, k, s); });
    else
      forward_pass<SphereGhostState>(
          *ranks_->comm, pass.sent, pass.first, pass.received, pass.to, pass.from, tag, out_, in_,
          [&](std::uint32_t k) { return sphere_state_of(p, k, pass.axis, pass.shift); },
          [&](std::size_t k, const SphereGhostState& s) { set_sphere_state(p, k, s); });
  }
}

void HaloExchange::reverse(ParticleStore& p) const {
  for (auto it = passes_.rbegin(); it != passes_.rend(); ++it) {
    const Pass& pass = *it;
    out_.resize(pass.received * 2 * sizeof(Vec3));
    for (std::size_t g = 0; g < pass.received; ++g) {
      std::memcpy(out_.data() + 2 * g * sizeof(Vec3), &p.force[pass.first + g], sizeof(Vec3));
      std::memcpy(out_.data() + (2 * g + 1) * sizeof(Vec3), &p.torque[pass.first + g], sizeof(Vec3));
    }
    in_.resize(pass.sent.size() * 2 * sizeof(Vec3));
    ranks_->comm->exchange_sized(out_, pass.from, pass.to, kReverseTag + pass.tag - kCreateTag, in_);
    if (in_.size() != pass.sent.size() * 2 * sizeof(Vec3)) throw std::logic_error("halo reverse exchange out of step");
    ByteReader r(in_);
    for (const std::uint32_t k : pass.sent) {
      p.force[k] += r.get<Vec3>();
      p.torque[k] += r.get<Vec3>();
    }
  }
}

}  // namespace talus
