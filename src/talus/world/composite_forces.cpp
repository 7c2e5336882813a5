// Contacts of rigid non-spherical bodies: every pair of convex parts whose bounding spheres
// touch goes through the narrow phase (Huet et al. 2021, Sec. II A); each contact point
// gets the same contact law as a sphere, with its own memory.
#include "talus/collide/convex_contact.h"
#include "talus/collide/convex_contact_analytic.h"
#include "talus/collide/manifold.h"
#include "talus/world/world.h"

namespace talus {

namespace {

// A sphere particle seen as a one-part composite.
const CompositeShape& shape_of(const std::vector<CompositeShape>& shapes, int index, double radius,
                               CompositeShape& scratch) {
  if (index != 0) return shapes[index];
  scratch.parts.clear();
  scratch.add(make_sphere(radius), Pose{});
  return scratch;
}

struct PointGeometry {
  Vec3 normal, point;
  double overlap;
  std::uint32_t feature;
};

// Contact points of two posed convex parts: a manifold, or the single deepest point.
int part_points(const ConvexShape& a, const Pose& pa, const ConvexShape& b, const Pose& pb, bool manifold,
                PointGeometry out[4]) {
  if (manifold) {
    const ContactManifold m = contact_manifold(a, pa, b, pb);
    for (int k = 0; k < m.count; ++k) out[k] = {m.normal, m.points[k].point, m.points[k].delta_n, m.points[k].feature_id};
    int n = 0;
    for (int k = 0; k < m.count; ++k)
      if (out[k].overlap > 0) out[n++] = out[k];
    return n;
  }
  const PartContact c = narrow_phase(a, pa, b, pb);
  if (!c.touching || !(c.delta_n > 0)) return 0;
  out[0] = {c.normal, c.point, c.delta_n, 0};
  return 1;
}

// Finds the memory of a contact point in last step's list.
const SubContact* find_previous(const SubContactList& previous, const SubContact& key) {
  for (const SubContact& s : previous)
    if (s.same_key(key)) return &s;
  return nullptr;
}

template <TangentialModel Model>
void apply_point(const PointGeometry& pg, double share, const ContactParams& params, double reduced_mass,
                 double reduced_radius, const Vec3& xi, const Vec3& xj, const ContactMotion& motion, double dt,
                 SubContact& s, ContactResult& total) {
  ContactParams shared = params;
  shared.normal_stiffness *= share;
  shared.normal_damping.coefficient *= share;
  shared.normal_damping.per_reduced_mass *= share;
  shared.normal_damping.per_sqrt_reduced_mass *= share;
  shared.tangential_stiffness *= share;
  shared.tangential_damping.coefficient *= share;
  shared.tangential_damping.per_reduced_mass *= share;
  shared.tangential_damping.per_sqrt_reduced_mass *= share;
  ContactGeometry g;
  g.normal = pg.normal;
  g.overlap = pg.overlap;
  g.arm_i = pg.point - xi;
  g.arm_j = pg.point - xj;
  g.inv_distance = 0;  // the memory turns with the normal through normal_prev
  const ContactResult r = contact_force<Model>(g, motion, shared, reduced_mass, reduced_radius, dt,
                                               {&s.spring, &s.normal_prev, nullptr});
  s.point = pg.point;
  s.force = r.force_on_i;
  s.overlap = pg.overlap;
  s.share = share;
  total.force_on_i += r.force_on_i;
  total.torque_i += r.torque_i;
  total.torque_j += r.torque_j;
  total.normal_force += r.normal_force;
}

}  // namespace

template <TangentialModel Model>
ContactResult World::composite_pair(std::size_t i, std::size_t j, SubContactList& contacts, double memory_dt) {
  const ParticleStore& p = particles_;
  CompositeShape scratch_i, scratch_j;
  const CompositeShape& si = shape_of(shapes_, p.shape[i], p.radius[i], scratch_i);
  const CompositeShape& sj = shape_of(shapes_, p.shape[j], p.radius[j], scratch_j);
  const Pose body_i{p.position[i], p.orientation[i]}, body_j{p.position[j], p.orientation[j]};
  const ContactParams& params = table_.pair(p.species[i], p.species[j]);
  const double reduced_mass = 1.0 / (p.inv_mass[i] + p.inv_mass[j]);
  const double reduced_radius = p.radius[i] * p.radius[j] / (p.radius[i] + p.radius[j]);
  const ContactMotion motion{p.velocity[i], p.angular_velocity[i], p.velocity[j], p.angular_velocity[j]};
  SubContactList previous;
  previous.swap(contacts);
  ContactResult total;
  for (std::size_t a = 0; a < si.parts.size(); ++a) {
    const Pose pa = body_i * si.parts[a].pose;
    const double ra = si.parts[a].shape.bounding_radius;
    for (std::size_t b = 0; b < sj.parts.size(); ++b) {
      const Pose pb = body_j * sj.parts[b].pose;
      const double reach = ra + sj.parts[b].shape.bounding_radius;
      if (norm2(pa.position - pb.position) >= reach * reach) continue;
      PointGeometry points[4];
      const int n = part_points(si.parts[a].shape, pa, sj.parts[b].shape, pb, settings_.contact_manifold, points);
      for (int k = 0; k < n; ++k) {
        SubContact s;
        s.part_i = static_cast<std::uint16_t>(a);
        s.part_j = static_cast<std::uint16_t>(b);
        s.feature = points[k].feature;
        if (const SubContact* old = find_previous(previous, s)) {
          s.spring = old->spring;
          s.normal_prev = old->normal_prev;
        }
        apply_point<Model>(points[k], 1.0 / n, params, reduced_mass, reduced_radius, p.position[i], p.position[j], motion,
                           memory_dt, s, total);
        contacts.push_back(s);
      }
    }
  }
  return total;
}

template <TangentialModel Model>
ContactResult World::composite_wall(std::size_t i, const Wall& wall, const Vec3& origin, const Vec3& wall_velocity,
                                    SubContactList& contacts, double memory_dt) {
  const ParticleStore& p = particles_;
  CompositeShape scratch;
  const CompositeShape& si = shape_of(shapes_, p.shape[i], p.radius[i], scratch);
  const Pose body{p.position[i], p.orientation[i]};
  const ContactParams& params = table_.wall(p.species[i], wall.material);
  const HalfSpace plane{wall.normal, dot(wall.normal, origin)};  // solid behind the wall, normal into the free side
  const ContactMotion motion{p.velocity[i], p.angular_velocity[i], wall_velocity, Vec3{}};
  SubContactList previous;
  previous.swap(contacts);
  ContactResult total;
  for (std::size_t a = 0; a < si.parts.size(); ++a) {
    const Pose pa = body * si.parts[a].pose;
    PointGeometry points[4];
    int n = 0;
    if (settings_.contact_manifold) {
      const ContactManifold m = convex_plane_manifold(si.parts[a].shape, pa, plane);
      for (int k = 0; k < m.count; ++k)
        if (m.points[k].delta_n > 0) points[n++] = {m.normal, m.points[k].point, m.points[k].delta_n, m.points[k].feature_id};
    } else {
      const PartContact c = convex_plane_contact(si.parts[a].shape, pa, plane);
      if (c.touching && c.delta_n > 0) points[n++] = {c.normal, c.point, c.delta_n, 0};
    }
    for (int k = 0; k < n; ++k) {
      if (wall.bounded && !wall_faces(wall, origin, points[k].point, 0.0)) continue;
      SubContact s;
      s.part_i = static_cast<std::uint16_t>(a);
      s.feature = points[k].feature;
      if (const SubContact* old = find_previous(previous, s)) {
        s.spring = old->spring;
        s.normal_prev = old->normal_prev;
      }
      apply_point<Model>(points[k], 1.0 / n, params, 1.0 / p.inv_mass[i], p.radius[i], p.position[i], points[k].point,
                         motion, memory_dt, s, total);
      contacts.push_back(s);
    }
  }
  return total;
}

#define TALUS_INSTANTIATE(M)                                                                                  \
  template ContactResult World::composite_pair<M>(std::size_t, std::size_t, SubContactList&, double);        \
  template ContactResult World::composite_wall<M>(std::size_t, const Wall&, const Vec3&, const Vec3&, SubContactList&, double);
TALUS_INSTANTIATE(TangentialModel::memory)
TALUS_INSTANTIATE(TangentialModel::memoryless)
TALUS_INSTANTIATE(TangentialModel::elastic_spring)
#undef TALUS_INSTANTIATE

}  // namespace talus
