// Contacts of rigid non-spherical bodies: every pair of convex parts whose bounding capsules
// touch goes through the narrow phase (Huet et al. 2021, Sec. II A); each contact point gets
// the same contact law as a sphere, with its own memory.
//
// Cost, per body pair whose bounding spheres overlap: the parts are placed once (pose, box axes,
// capsule), each part pair is culled by its capsules (segment distance), and only the survivors
// run the narrow phase, warm-started from the contact they made last step (SAT axis from the
// manifold feature id, GJK direction from the previous normal). No heap traffic once the
// per-entry lists have grown.
#include <x86intrin.h>

#include <cmath>
#include <new>
#include <type_traits>
#include <variant>

#include "talus/collide/box_box.h"
#include "talus/collide/convex_contact.h"
#include "talus/collide/convex_contact_analytic.h"
#include "talus/collide/manifold.h"
#include "talus/world/composite_stats.h"
#include "talus/world/world.h"

namespace talus {

namespace {

// A sphere particle seen as a one-part composite (per thread: no allocation after the first).
const CompositeShape& shape_of(const std::vector<CompositeShape>& shapes, int index, double radius,
                               CompositeShape& scratch) {
  if (index != 0) return shapes[index];
  scratch.parts.clear();
  scratch.bounding_radius = 0;
  scratch.add(make_sphere(radius), Pose{});
  return scratch;
}

// A part placed in the world for one body pair.
struct PlacedPart {
  Pose pose;
  OrientedBox box;      ///< axes always set; centre and half extents too when the part is a box
  Vec3 capsule_axis;    ///< world half-axis of the culling capsule (m)
  double capsule_radius = 0;
  bool is_box = false;
};

// Storage for a PlacedPart constructed only when needed (no zeroing of unused slots).
union PlacedSlot {
  PlacedPart part;
  PlacedSlot() {}
};
static_assert(std::is_trivially_destructible_v<PlacedPart>);

PlacedPart place(const CompositePart& part, const Pose& body) {
  PlacedPart p;
  p.pose = body * part.pose;
  rotation_axes(p.pose.orientation, p.box.axis);
  p.box.centre = p.pose.position;
  const Vec3 c = part.capsule.half_axis;
  p.capsule_axis = p.box.axis[0] * c.x + p.box.axis[1] * c.y + p.box.axis[2] * c.z;
  p.capsule_radius = part.capsule.radius;
  if (const Box* b = std::get_if<Box>(&part.shape.geometry)) {
    p.box.half = b->half_extents;
    p.is_box = true;
  }
  return p;
}

struct PointGeometry {
  Vec3 normal, point;
  double overlap;
  std::uint32_t feature;
};

// The SAT axis a box-box manifold point was made on, from its feature id (manifold.h):
// reference face (0-5 on A, 6-11 on B) in the top byte, or 0xFF and the edge axis.
int sat_axis_of(std::uint32_t feature) {
  const std::uint32_t top = feature >> 24;
  if (top == 0xFF) return static_cast<int>(feature & 0xFF);
  if (top < 6) return static_cast<int>(top / 2);
  if (top < 12) return static_cast<int>(3 + (top - 6) / 2);
  return -1;
}

// Contact points of two placed convex parts: a manifold, or the single deepest point.
// `previous` is this part pair's contact of last step (or null), for the warm start.
int part_points(const ConvexShape& a, const PlacedPart& pa, const ConvexShape& b, const PlacedPart& pb, bool manifold,
                const SubContact* previous, PointGeometry out[4]) {
  ContactCache warm;
  if (previous) warm.separation = previous->normal_prev;  // GJK: the core separation is along the normal
  if (manifold) {
    ContactManifold m;
    if (pa.is_box && pb.is_box) {
      const BoxBoxSat sat = box_box_sat(pa.box, pb.box, previous ? sat_axis_of(previous->feature) : -1);
      if (sat.separated) return 0;
      m = box_box_manifold(pa.box, pb.box, sat);
    } else {
      m = contact_manifold(a, pa.pose, b, pb.pose, &warm);
    }
    int n = 0;
    for (int k = 0; k < m.count; ++k)
      if (m.points[k].delta_n > 0) out[n++] = {m.normal, m.points[k].point, m.points[k].delta_n, m.points[k].feature_id};
    return n;
  }
  const PartContact c = narrow_phase(a, pa.pose, b, pb.pose, &warm);
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

const SubContact* find_part_pair(const SubContactList& previous, std::uint16_t a, std::uint16_t b) {
  for (const SubContact& s : previous)
    if (s.part_i == a && s.part_j == b) return &s;
  return nullptr;
}

// The parameters of one point of an n-point manifold: k and eta divided by n.
ContactParams shared_params(const ContactParams& params, double share) {
  ContactParams shared = params;
  shared.normal_stiffness *= share;
  shared.normal_damping.coefficient *= share;
  shared.normal_damping.per_reduced_mass *= share;
  shared.normal_damping.per_sqrt_reduced_mass *= share;
  shared.tangential_stiffness *= share;
  shared.tangential_damping.coefficient *= share;
  shared.tangential_damping.per_reduced_mass *= share;
  shared.tangential_damping.per_sqrt_reduced_mass *= share;
  return shared;
}

template <TangentialModel Model>
void apply_point(const PointGeometry& pg, double share, const ContactParams& params, double reduced_mass,
                 double reduced_radius, const Vec3& xi, const Vec3& xj, const ContactMotion& motion, double dt,
                 SubContact& s, ContactResult& total) {
  ContactGeometry g;
  g.normal = pg.normal;
  g.overlap = pg.overlap;
  g.arm_i = pg.point - xi;
  g.arm_j = pg.point - xj;
  g.inv_distance = 0;  // the memory turns with the normal through normal_prev
  const ContactHistoryRef h{&s.spring, &s.normal_prev, nullptr};
  const ContactResult r = share == 1.0
                              ? contact_force<Model>(g, motion, params, reduced_mass, reduced_radius, dt, h)
                              : contact_force<Model>(g, motion, shared_params(params, share), reduced_mass,
                                                     reduced_radius, dt, h);
  s.point = pg.point;
  s.force = r.force_on_i;
  s.overlap = pg.overlap;
  s.share = share;
  total.force_on_i += r.force_on_i;
  total.torque_i += r.torque_i;
  total.torque_j += r.torque_j;
  total.normal_force += r.normal_force;
}

// A body's rotation as its three axes in the world (columns of the rotation matrix).
struct BodyFrame {
  Vec3 position;
  Vec3 axis[3];
  Vec3 to_world(const Vec3& v) const { return axis[0] * v.x + axis[1] * v.y + axis[2] * v.z; }
};

BodyFrame body_frame(const Vec3& x, const Quat& q) {
  BodyFrame f;
  f.position = x;
  rotation_axes(q, f.axis);
  return f;
}

// Body-level cull: the 6 face axes of the two bodies' part-bounding boxes (Gottschalk et al.
// 1996). A separating face axis proves no part pair can touch.
bool body_boxes_apart(const CompositeShape& si, const BodyFrame& fi, const CompositeShape& sj, const BodyFrame& fj) {
  const Vec3* A = fi.axis;
  const Vec3* B = fj.axis;
  const Vec3 d = fj.position + fj.to_world(sj.box_centre) - fi.position - fi.to_world(si.box_centre);
  const Vec3& ha = si.box_half;
  const Vec3& hb = sj.box_half;
  double absR[3][3];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) absR[i][j] = std::abs(dot(A[i], B[j]));
    if (std::abs(dot(d, A[i])) > ha[i] + hb[0] * absR[i][0] + hb[1] * absR[i][1] + hb[2] * absR[i][2]) return true;
  }
  for (int j = 0; j < 3; ++j)
    if (std::abs(dot(d, B[j])) > hb[j] + ha[0] * absR[0][j] + ha[1] * absR[1][j] + ha[2] * absR[2][j]) return true;
  return false;
}

// A part's culling capsule in the world: centre and half-axis (the radius is the part's).
struct WorldCapsule {
  Vec3 centre, half_axis;
};

WorldCapsule world_capsule(const CompositePart& part, const BodyFrame& f) {
  return {f.position + f.to_world(part.pose.position), f.to_world(part.pose.orientation.rotate(part.capsule.half_axis))};
}

// Last step's list, moved aside while this step's is written (per thread, reused).
SubContactList& previous_scratch(const SubContactList& contacts) {
  thread_local SubContactList previous;
  previous.assign(contacts.begin(), contacts.end());
  return previous;
}

std::uint64_t ticks(bool on) { return on ? __rdtsc() : 0; }

}  // namespace

template <TangentialModel Model>
ContactResult World::composite_pair(std::size_t i, std::size_t j, SubContactList& contacts, double memory_dt) {
  const bool profile = composite_stats_enabled();
  const std::uint64_t t_start = ticks(profile);
  std::uint64_t t_cull = 0, t_narrow = 0, t_force = 0, n_parts = 0, n_narrow = 0, n_points = 0;
  const ParticleStore& p = particles_;
  thread_local CompositeShape scratch_i, scratch_j;
  const CompositeShape& si = shape_of(shapes_, p.shape[i], p.radius[i], scratch_i);
  const CompositeShape& sj = shape_of(shapes_, p.shape[j], p.radius[j], scratch_j);
  const BodyFrame frame_i = body_frame(p.position[i], p.orientation[i]);
  const BodyFrame frame_j = body_frame(p.position[j], p.orientation[j]);
  if (body_boxes_apart(si, frame_i, sj, frame_j)) {
    contacts.clear();
    if (profile) {
      CompositeStats& st = composite_stats_slot();
      ++st.body_pairs;
      st.total_ticks += ticks(profile) - t_start;
    }
    return {};
  }
  const Pose body_i{p.position[i], p.orientation[i]}, body_j{p.position[j], p.orientation[j]};
  const ContactParams& params = table_.pair(p.species[i], p.species[j]);
  const double reduced_mass = 1.0 / (p.inv_mass[i] + p.inv_mass[j]);
  const double reduced_radius = p.radius[i] * p.radius[j] / (p.radius[i] + p.radius[j]);
  const ContactMotion motion{p.velocity[i], p.angular_velocity[i], p.velocity[j], p.angular_velocity[j]};
  const SubContactList& previous = previous_scratch(contacts);
  contacts.clear();

  // Capsules of every part first; a part is placed (pose, box axes) only when one of its pairs
  // survives the capsule cull. Composites of up to 4 parts on the stack.
  constexpr std::size_t kMaxParts = 4;
  const std::size_t ni = si.parts.size(), nj = sj.parts.size();
  thread_local std::vector<WorldCapsule> overflow_ci, overflow_cj;
  thread_local std::vector<PlacedSlot> overflow_i, overflow_j;
  thread_local std::vector<char> overflow_pi, overflow_pj;
  WorldCapsule stack_ci[kMaxParts], stack_cj[kMaxParts];
  PlacedSlot stack_i[kMaxParts], stack_j[kMaxParts];
  char stack_pi[kMaxParts] = {}, stack_pj[kMaxParts] = {};
  WorldCapsule* cap_i = stack_ci;
  WorldCapsule* cap_j = stack_cj;
  PlacedSlot* placed_i = stack_i;
  PlacedSlot* placed_j = stack_j;
  char* is_placed_i = stack_pi;
  char* is_placed_j = stack_pj;
  if (ni > kMaxParts) {
    overflow_ci.resize(ni), overflow_i.resize(ni), overflow_pi.assign(ni, 0);
    cap_i = overflow_ci.data(), placed_i = overflow_i.data(), is_placed_i = overflow_pi.data();
  }
  if (nj > kMaxParts) {
    overflow_cj.resize(nj), overflow_j.resize(nj), overflow_pj.assign(nj, 0);
    cap_j = overflow_cj.data(), placed_j = overflow_j.data(), is_placed_j = overflow_pj.data();
  }
  for (std::size_t a = 0; a < ni; ++a) cap_i[a] = world_capsule(si.parts[a], frame_i);
  for (std::size_t b = 0; b < nj; ++b) cap_j[b] = world_capsule(sj.parts[b], frame_j);

  ContactResult total;
  std::uint64_t t0 = ticks(profile);
  for (std::size_t a = 0; a < ni; ++a) {
    for (std::size_t b = 0; b < nj; ++b) {
      ++n_parts;
      if (capsules_apart(cap_i[a].centre, cap_i[a].half_axis, si.parts[a].capsule.radius, cap_j[b].centre,
                         cap_j[b].half_axis, sj.parts[b].capsule.radius))
        continue;
      ++n_narrow;
      if (!is_placed_i[a]) new (&placed_i[a].part) PlacedPart(place(si.parts[a], body_i)), is_placed_i[a] = 1;
      if (!is_placed_j[b]) new (&placed_j[b].part) PlacedPart(place(sj.parts[b], body_j)), is_placed_j[b] = 1;
      const PlacedPart& pa = placed_i[a].part;
      const PlacedPart& pb = placed_j[b].part;
      const std::uint64_t t1 = ticks(profile);
      t_cull += t1 - t0;
      const auto part_a = static_cast<std::uint16_t>(a), part_b = static_cast<std::uint16_t>(b);
      PointGeometry points[4];
      const int n = part_points(si.parts[a].shape, pa, sj.parts[b].shape, pb, settings_.contact_manifold,
                                find_part_pair(previous, part_a, part_b), points);
      const std::uint64_t t2 = ticks(profile);
      t_narrow += t2 - t1;
      for (int k = 0; k < n; ++k) {
        SubContact s;
        s.part_i = part_a;
        s.part_j = part_b;
        s.feature = points[k].feature;
        if (const SubContact* old = find_previous(previous, s)) {
          s.spring = old->spring;
          s.normal_prev = old->normal_prev;
        }
        apply_point<Model>(points[k], 1.0 / n, params, reduced_mass, reduced_radius, p.position[i], p.position[j], motion,
                           memory_dt, s, total);
        contacts.push_back(s);
      }
      n_points += static_cast<std::uint64_t>(n);
      t0 = ticks(profile);
      t_force += t0 - t2;
    }
  }
  if (profile) {
    const std::uint64_t t_end = ticks(profile);
    t_cull += t_end - t0;
    CompositeStats& st = composite_stats_slot();
    ++st.body_pairs;
    st.part_pairs += n_parts;
    st.narrow += n_narrow;
    st.points += n_points;
    st.cull_ticks += t_cull;
    st.narrow_ticks += t_narrow;
    st.force_ticks += t_force;
    st.total_ticks += t_end - t_start;
  }
  return total;
}

template <TangentialModel Model>
ContactResult World::composite_wall(std::size_t i, const Wall& wall, const Vec3& origin, const Vec3& wall_velocity,
                                    SubContactList& contacts, double memory_dt) {
  const ParticleStore& p = particles_;
  thread_local CompositeShape scratch;
  const CompositeShape& si = shape_of(shapes_, p.shape[i], p.radius[i], scratch);
  const Pose body{p.position[i], p.orientation[i]};
  const ContactParams& params = table_.wall(p.species[i], wall.material);
  const HalfSpace plane{wall.normal, dot(wall.normal, origin)};  // solid behind the wall, normal into the free side
  const ContactMotion motion{p.velocity[i], p.angular_velocity[i], wall_velocity, Vec3{}};
  const SubContactList& previous = previous_scratch(contacts);
  contacts.clear();
  ContactResult total;
  for (std::size_t a = 0; a < si.parts.size(); ++a) {
    const Pose pa = body * si.parts[a].pose;
    // The part's bounding sphere clears the plane: no corner can touch it.
    if (dot(pa.position, plane.normal) - plane.offset >= si.parts[a].shape.bounding_radius) continue;
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
TALUS_INSTANTIATE(TangentialModel::elastic_spring)
TALUS_INSTANTIATE(TangentialModel::memoryless)
#undef TALUS_INSTANTIATE

}  // namespace talus
