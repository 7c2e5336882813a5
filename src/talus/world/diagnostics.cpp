// Energies, contact counts and snapshots of a World: read-only passes outside the time step.
#include <algorithm>
#include <cmath>

#include "talus/world/distributed_snapshot.h"
#include "talus/world/memory_ref.h"
#include "talus/world/world.h"

namespace talus {

namespace {
// k_r of a contact, as the contact law computes it (Huet et al. 2021, Eq. A9 when from_normal).
double rolling_stiffness(const ContactParams& c, double reduced_radius, double kn) {
  if (!c.rolling.from_normal) return c.rolling.stiffness;
  const double r = 2 * reduced_radius;
  return 3 * c.rolling.friction * c.rolling.friction * r * r * kn;
}

void add_contact_energy(Diagnostics& d, const ContactParams& c, double overlap, double radius,
                        double reduced_radius, const ContactMemory& mem, std::size_t e) {
  const ContactCoefficients k = contact_coefficients(c, 0, reduced_radius, overlap);
  d.elastic_normal += normal_elastic_energy(c, k.kn, overlap);
  if (!mem.spring.empty()) d.elastic_tangential += 0.5 * k.kt * norm2(mem.spring[e]);
  if (!mem.rolling.empty() && c.rolling.enabled) {
    const double kr = rolling_stiffness(c, reduced_radius, k.kn);
    if (kr > 0) d.elastic_rolling += 0.5 * norm2(mem.rolling[e]) / kr;
  }
  d.max_overlap_ratio = std::max(d.max_overlap_ratio, overlap / radius);
}
}  // namespace

Diagnostics World::diagnostics() const {
  if (!distributed()) return local_diagnostics();
  // Sums and maxima over the ranks; the mean speed from the ranks' sums of speeds.
  const Communicator& comm = communicator();
  Diagnostics d = local_diagnostics();
  double mobile = 0;
  for (std::size_t i = 0; i < particles_.owned; ++i) mobile += particles_.inv_mass[i] != 0.0;
  std::vector<double> sums{d.kinetic_translational, d.kinetic_rotational, d.elastic_normal, d.elastic_tangential,
                           d.elastic_rolling,       d.gravitational,      static_cast<double>(d.contacts),
                           static_cast<double>(d.wall_contacts), d.mean_speed * mobile, mobile};
  comm.sum_in_place(sums);
  d.kinetic_translational = sums[0];
  d.kinetic_rotational = sums[1];
  d.elastic_normal = sums[2];
  d.elastic_tangential = sums[3];
  d.elastic_rolling = sums[4];
  d.gravitational = sums[5];
  d.contacts = static_cast<std::size_t>(sums[6]);
  d.wall_contacts = static_cast<std::size_t>(sums[7]);
  d.mean_speed = sums[9] > 0 ? sums[8] / sums[9] : 0;
  d.max_overlap_ratio = comm.max(d.max_overlap_ratio);
  d.max_speed = comm.max(d.max_speed);
  d.max_angular_speed = comm.max(d.max_angular_speed);
  return d;
}

Diagnostics World::local_diagnostics() const {
  Diagnostics d;
  d.time = time_;
  const ParticleStore& p = particles_;
  std::size_t mobile = 0;
  double speed_sum = 0;
  for (std::size_t i = 0; i < p.owned; ++i) {
    if (p.inv_mass[i] == 0.0) continue;
    ++mobile;
    const double m = p.mass[i];
    const double v2 = norm2(p.velocity[i]);
    d.kinetic_translational += 0.5 * m * v2;
    const Vec3 wb = p.orientation[i].rotate_inverse(p.angular_velocity[i]);
    const Vec3 ii = p.inv_inertia[i];
    d.kinetic_rotational += 0.5 * (wb.x * wb.x / ii.x + wb.y * wb.y / ii.y + wb.z * wb.z / ii.z);
    d.gravitational -= m * dot(settings_.gravity, p.position[i]);
    const double speed = std::sqrt(v2);
    speed_sum += speed;
    d.max_speed = std::max(d.max_speed, speed);
    d.max_angular_speed = std::max(d.max_angular_speed, norm(p.angular_velocity[i]));
  }
  d.mean_speed = mobile ? speed_sum / mobile : 0;
  if (!ready_) return d;
  // Shaped bodies take the linear law only (the scenario reader refuses the others for them).
  auto add_points = [&](std::span<const SubContact> list, const ContactParams& c, double radius) {
    for (const SubContact& s : list) {
      d.elastic_normal += 0.5 * s.share * c.normal_stiffness * s.overlap * s.overlap;
      d.elastic_tangential += 0.5 * s.share * c.tangential_stiffness * norm2(s.spring);
      d.max_overlap_ratio = std::max(d.max_overlap_ratio, s.overlap / radius);
    }
  };
  for (std::size_t i = 0; i < lists_.pairs.rows(); ++i)
    for (std::uint32_t e = lists_.pairs.row_begin(i); e < lists_.pairs.row_end(i); ++e) {
      const std::uint32_t j = lists_.pairs.neighbor(e);
      if (p.shape[i] != 0 || p.shape[j] != 0) {
        d.contacts += shaped_.pair_points.of(e).size();
        add_points(shaped_.pair_points.of(e), table_.pair(p.species[i], p.species[j]), std::min(p.radius[i], p.radius[j]));
        continue;
      }
      const double reach = p.radius[i] + p.radius[j];
      const double overlap = reach - norm(p.position[i] - p.position[j]);
      if (overlap <= 0) continue;
      ++d.contacts;
      add_contact_energy(d, table_.pair(p.species[i], p.species[j]), overlap, std::min(p.radius[i], p.radius[j]),
                         p.radius[i] * p.radius[j] / reach, lists_.pairs.memory, e);
    }
  for (std::size_t i = 0; i < lists_.walls.rows(); ++i)
    for (std::uint32_t e = lists_.walls.row_begin(i); e < lists_.walls.row_end(i); ++e) {
      const Wall& w = walls_[lists_.walls.wall(e)];
      if (!w.active(time_) || p.inv_mass[i] == 0.0) continue;
      if (p.shape[i] != 0) {
        d.wall_contacts += shaped_.wall_points.of(e).size();
        add_points(shaped_.wall_points.of(e), table_.wall(p.species[i], w.material), p.radius[i]);
        continue;
      }
      SphereWallTouch touch;
      if (!sphere_touches_wall(w, w.origin_at(time_), p.position[i], p.radius[i], touch)) continue;
      ++d.wall_contacts;
      add_contact_energy(d, table_.wall(p.species[i], w.material), touch.overlap, p.radius[i], p.radius[i],
                         lists_.walls.memory, e);
    }
  return d;
}

Snapshot World::snapshot() const {
  return distributed() ? gather_snapshot(local_snapshot(PartnerNames::kGlobalId), communicator(), next_gid_)
                       : local_snapshot(PartnerNames::kRecord);
}

Snapshot World::snapshot_on_first_rank() const {
  return distributed() ? gather_snapshot(local_snapshot(PartnerNames::kGlobalId), communicator(), next_gid_, 0)
                       : local_snapshot(PartnerNames::kRecord);
}

World::SnapshotPiece World::snapshot_piece() const {
  SnapshotPiece piece;
  piece.snapshot = local_snapshot(PartnerNames::kRecordWithGhosts, &piece.owned);
  return piece;
}

Snapshot World::local_snapshot(PartnerNames names, std::size_t* owned_records) const {
  Snapshot s;
  s.time = time_;
  s.gravity = settings_.gravity;
  s.domain_min = settings_.domain.lo;
  s.domain_max = settings_.domain.hi;
  for (int a = 0; a < 3; ++a) s.periodic[a] = settings_.domain.periodic[a];
  const ParticleStore& p = particles_;
  // Particles in global-id order, so that snapshots of a run line up.
  std::vector<std::uint32_t> order(p.owned);
  for (std::size_t i = 0; i < p.owned; ++i) order[i] = static_cast<std::uint32_t>(i);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return p.gid[a] < p.gid[b]; });
  const bool by_gid = names == PartnerNames::kGlobalId;
  std::vector<int> record_of(p.owned);
  s.particles.reserve(p.owned);
  const auto record = [&](std::size_t i) {
    ParticleRecord r;
    r.id = p.gid[i];
    r.species = p.species[i];
    r.shape = p.shape[i];
    r.fixed = p.inv_mass[i] == 0.0;
    r.mass = p.mass[i];
    r.radius = p.radius[i];
    r.volume = 4.0 / 3.0 * 3.14159265358979323846 * r.radius * r.radius * r.radius;
    r.position = settings_.domain.wrap(p.position[i]);
    r.velocity = p.velocity[i];
    r.angular_velocity = p.angular_velocity[i];
    r.orientation = p.orientation[i];
    return r;
  };
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::uint32_t i = order[k];
    record_of[i] = by_gid ? static_cast<int>(p.gid[i]) : static_cast<int>(k);
    s.particles.push_back(record(i));
  }
  if (owned_records) *owned_records = s.particles.size();
  if (!ready_) return s;
  // Periodic images are named by their owner; copies from other ranks by their global id,
  // or by a record of their own appended to the piece.
  std::vector<int> halo_record(names == PartnerNames::kRecordWithGhosts ? p.size() - p.owned - lists_.ghosts.count() : 0, -1);
  const auto record_of_neighbor = [&](std::uint32_t j) {
    if (j < p.owned) return record_of[j];
    const std::size_t g = j - p.owned;
    if (g < lists_.ghosts.count()) return record_of[lists_.ghosts.owner(g)];
    if (by_gid) return static_cast<int>(p.gid[j]);
    int& r = halo_record[g - lists_.ghosts.count()];
    if (r < 0) {
      r = static_cast<int>(s.particles.size());
      s.particles.push_back(record(j));
    }
    return r;
  };
  if (!ready_) return s;
  // Contact forces are re-evaluated from the stored memories with the current velocities.
  ContactMemory scratch = lists_.pairs.memory;
  for (std::size_t i = 0; i < lists_.pairs.rows(); ++i)
    for (std::uint32_t e = lists_.pairs.row_begin(i); e < lists_.pairs.row_end(i); ++e) {
      const std::uint32_t j = lists_.pairs.neighbor(e);
      if (p.shape[i] != 0 || p.shape[j] != 0) {
        for (const SubContact& sc : shaped_.pair_points.of(e)) {
          ContactRecord rec;
          rec.i = record_of[i];
          rec.j = record_of_neighbor(j);
          rec.point = settings_.domain.wrap(sc.point);
          rec.normal = sc.normal_prev;
          rec.force = sc.force;
          rec.overlap = sc.overlap;
          s.contacts.push_back(rec);
        }
        continue;
      }
      const Vec3 d = p.position[i] - p.position[j];
      const double reach = p.radius[i] + p.radius[j];
      const double dist = norm(d);
      if (dist >= reach) continue;
      ContactGeometry g;
      g.normal = d / dist;
      g.overlap = reach - dist;
      g.arm_i = g.normal * -(p.radius[i] - 0.5 * g.overlap);
      g.arm_j = g.normal * (p.radius[j] - 0.5 * g.overlap);
      g.inv_distance = 1 / dist;
      const ContactMotion m{p.velocity[i], p.angular_velocity[i], p.velocity[j], p.angular_velocity[j]};
      const ContactHistoryRef h = memory_ref(scratch, e);
      const ContactParams& c = table_.pair(p.species[i], p.species[j]);
      const double mij = 1 / (p.inv_mass[i] + p.inv_mass[j]);
      const double rij = p.radius[i] * p.radius[j] / reach;
      const ContactResult res = with_tangential_model(
          settings_.tangential_model, [&](auto model) { return contact_force<model.value>(g, m, c, mij, rij, 0, h); });
      ContactRecord rec;
      rec.i = record_of[i];
      rec.j = record_of_neighbor(j);
      rec.point = settings_.domain.wrap(p.position[i] + g.arm_i);
      rec.normal = g.normal;
      rec.force = res.force_on_i;
      rec.overlap = g.overlap;
      s.contacts.push_back(rec);
    }
  for (std::size_t i = 0; i < lists_.walls.rows(); ++i)
    for (std::uint32_t e = lists_.walls.row_begin(i); e < lists_.walls.row_end(i); ++e) {
      const Wall& w = walls_[lists_.walls.wall(e)];
      if (!w.active(time_) || p.inv_mass[i] == 0.0) continue;
      if (p.shape[i] != 0) {
        for (const SubContact& sc : shaped_.wall_points.of(e)) {
          ContactRecord rec;
          rec.i = record_of[i];
          rec.wall = lists_.walls.wall(e);
          rec.point = sc.point;
          rec.normal = sc.normal_prev;
          rec.force = sc.force;
          rec.overlap = sc.overlap;
          s.contacts.push_back(rec);
        }
        continue;
      }
      SphereWallTouch touch;
      if (!sphere_touches_wall(w, w.origin_at(time_), p.position[i], p.radius[i], touch)) continue;
      ContactRecord rec;
      rec.i = record_of[i];
      rec.wall = lists_.walls.wall(e);
      rec.normal = touch.normal;
      rec.point = p.position[i] - touch.normal * (p.radius[i] - 0.5 * touch.overlap);
      rec.force = -lists_.walls.force_on_wall[e];
      rec.overlap = touch.overlap;
      s.contacts.push_back(rec);
    }
  return s;
}

}  // namespace talus
