#include "talus/parallel/halo_exchange.h"

#include <stdexcept>

namespace talus {

namespace {
// Message tags: creation, the forward and the reverse exchange each use two (sizes, bytes).
constexpr int kCreateTag = 100, kForwardTag = 102, kReverseTag = 104;

struct GhostState {
  Vec3 position, velocity, angular_velocity;
  Quat orientation;
};

// The state a ghost takes from its original, shifted across the periodic face; its force is reset.
GhostState state_of(const ParticleStore& p, std::size_t k, int axis, double shift) {
  GhostState s{p.position[k], p.velocity[k], p.angular_velocity[k], p.orientation[k]};
  s.position[axis] += shift;
  return s;
}

void set_state(ParticleStore& p, std::size_t k, const GhostState& s) {
  p.position[k] = s.position;
  p.velocity[k] = s.velocity;
  p.angular_velocity[k] = s.angular_velocity;
  p.orientation[k] = s.orientation;
  p.force[k] = {};
  p.torque[k] = {};
}

struct GhostConstants {
  double radius, inv_mass, mass;
  Vec3 inv_inertia;
  std::int32_t species, shape;
  std::uint32_t gid;
};
}  // namespace

void HaloExchange::create(ParticleStore& p, const SlabDecomposition& slabs, const CellGrid& grid, double band,
                          std::vector<CellCoord>& cell_of) {
  slabs_ = &slabs;
  const int axis = slabs.axis;
  const double lo = slabs.lo();
  shift_ = slabs.rank() == 0 && slabs.periodic ? slabs.length : 0.0;
  sent_index_.clear();
  for (std::size_t k = 0; k < p.size(); ++k)
    if (p.position[k][axis] - lo < band) sent_index_.push_back(static_cast<std::uint32_t>(k));

  std::vector<std::byte> out;
  ByteWriter w(out);
  w.put(static_cast<std::uint64_t>(sent_index_.size()));
  for (const std::uint32_t k : sent_index_) {
    w.put(state_of(p, k, axis, shift_));
    w.put(GhostConstants{p.radius[k], p.inv_mass[k], p.mass[k], p.inv_inertia[k], p.species[k], p.shape[k], p.gid[k]});
  }
  const std::vector<std::byte> in = slabs.comm->exchange(out, slabs.lower(), slabs.upper(), kCreateTag);

  first_ = p.size();
  received_ = 0;
  if (in.empty()) return;
  ByteReader r(in);
  received_ = r.get<std::uint64_t>();
  p.resize(first_ + received_);
  cell_of.resize(first_ + received_);
  for (std::size_t g = 0; g < received_; ++g) {
    const std::size_t k = first_ + g;
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
    cell_of[k] = grid.halo_coord_of(s.position);
  }
}

// Between rebuilds both sides know the message sizes: one message each way.
void HaloExchange::forward(ParticleStore& p) const {
  const int axis = slabs_->axis;
  out_.clear();
  ByteWriter w(out_);
  for (const std::uint32_t k : sent_index_) w.put(state_of(p, k, axis, shift_));
  in_.resize(received_ * sizeof(GhostState));
  slabs_->comm->exchange_sized(out_, slabs_->lower(), slabs_->upper(), kForwardTag, in_);
  if (in_.size() != received_ * sizeof(GhostState)) throw std::logic_error("halo forward exchange out of step");
  ByteReader r(in_);
  for (std::size_t g = 0; g < received_; ++g) set_state(p, first_ + g, r.get<GhostState>());
}

void HaloExchange::reverse(ParticleStore& p) const {
  out_.clear();
  ByteWriter w(out_);
  for (std::size_t g = 0; g < received_; ++g) {
    w.put(p.force[first_ + g]);
    w.put(p.torque[first_ + g]);
  }
  in_.resize(sent_index_.size() * 2 * sizeof(Vec3));
  slabs_->comm->exchange_sized(out_, slabs_->upper(), slabs_->lower(), kReverseTag, in_);
  if (in_.size() != sent_index_.size() * 2 * sizeof(Vec3)) throw std::logic_error("halo reverse exchange out of step");
  ByteReader r(in_);
  for (const std::uint32_t k : sent_index_) {
    p.force[k] += r.get<Vec3>();
    p.torque[k] += r.get<Vec3>();
  }
}

}  // namespace talus
