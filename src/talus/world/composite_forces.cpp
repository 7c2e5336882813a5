// Contacts of rigid non-spherical bodies: every pair of convex parts whose bounding capsules
// touch goes through the narrow phase (Huet et al. 2021, Sec. II A); each contact point gets
// the same contact law as a sphere, with its own memory.
//
// Cost, per body pair whose bounding spheres overlap: the parts are placed once (pose, box axes,
// capsule), each part pair not asleep (pair_budgets.h) is culled by its capsules (segment
// distance), and only the survivors run the narrow phase, warm-started from the contact they
// made last step (SAT axis from the manifold feature id; GJK from last step's simplex, or its
// normal with contact.gjk_warm_start off). No heap traffic once the per-entry lists have grown.
#include <omp.h>
#include <x86intrin.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <type_traits>
#include <variant>

#if defined(__AVX2__)
#define TALUS_COMPOSITE_AVX2 1  // <x86intrin.h> above brings the intrinsics
#endif

#include "talus/collide/box_box.h"
#include "talus/collide/convex_contact.h"
#include "talus/collide/convex_contact_analytic.h"
#include "talus/collide/manifold.h"
#include "talus/math/uninitialized_array.h"
#include "talus/world/box_pair_reuse.h"
#include "talus/world/composite_stats.h"
#include "talus/world/memory_ref.h"
#include "talus/world/parallel.h"
#include "talus/world/placed_bodies.h"
#include "talus/world/sphere_contact.h"
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

struct PointGeometry {
  Vec3 normal, point;
  double overlap;
  std::uint32_t feature;
  const SubContact* recycled = nullptr;  ///< the record whose anchors gave the point (manifold_recycle)
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

// The points of a manifold that overlap, as contact geometry.
int touching_points(const ContactManifold& m, PointGeometry out[4]) {
  int n = 0;
  for (int k = 0; k < m.count; ++k)
    if (m.points[k].delta_n > 0) out[n++] = {m.normal, m.points[k].point, m.points[k].delta_n, m.points[k].feature_id};
  return n;
}

// The deepest overlap of a manifold's points.
double deepest(const ContactManifold& m) {
  double d = 0;
  for (int k = 0; k < m.count; ++k) d = std::max(d, m.points[k].delta_n);
  return d;
}

// A placed box part's core (the box eroded by its crust), placed as the part is.
OrientedBox core_box(const PlacedPart& placed, const CompositePart& part) {
  OrientedBox core = placed.box;
  core.half = std::get<Box>(part.shape.core).half_extents;
  return core;
}

// How two boxes' points were found.
enum class BoxQuery { full, stored_feature, refit, recycled, apart_axis };

// Last step's points of a part pair, served from their anchors (WorldSettings::manifold_recycle);
// points whose anchors have parted are dropped.
int recycled_points(const OrientedBox& a, const OrientedBox& b, const SubContact* previous,
                    const SubContact* previous_end, PointGeometry out[4]) {
  int n = 0;
  for (const SubContact* s = previous; s != previous_end && n < 4 && s->part_i == previous->part_i &&
                                       s->part_j == previous->part_j;
       ++s) {
    const AnchoredPoint q = from_anchors(a, b, s->anchors);
    if (q.overlap > 0) out[n++] = {q.normal, q.point, q.overlap, s->feature, s};
  }
  return n;
}

// Contact points of two placed convex parts: a manifold, or the single deepest point.
// [previous, previous_end) are this part pair's points of last step (empty: none), for the warm
// start and the stored features. With no point, *gap is a lower bound of the parts' distance
// when the test found one, else 0. *query says how two boxes' points were found.
int part_points(const CompositePart& a, const PlacedPart& pa, const Quat& body_a, const CompositePart& b,
                const PlacedPart& pb, const Quat& body_b, bool manifold, const Reuse& reuse, const SubContact* previous,
                const SubContact* previous_end, const PairMotion& motion, PartBudget& budget, PointGeometry out[4],
                double* gap, BoxQuery* query) {
  *gap = 0;
  *query = BoxQuery::stored_feature;
  ContactCache warm;
  warm.keep_simplex = !manifold && reuse.gjk_warm_start;
  if (previous) {
    warm.separation = previous->normal_prev;  // GJK: the core separation is along the normal
    if (warm.keep_simplex) warm.simplex = previous->feature;
  }
  if (manifold) {
    // The manifold is read where it was returned: declaring it first and assigning it cost a
    // memset and a memmove of its ~400 bytes per touching part pair.
    if (pa.is_box && pb.is_box) {
      const int stored_axis = previous ? sat_axis_of(previous->feature) : -1;
      if (recycle_allowed(reuse, budget, stored_axis, motion.travelled)) {
        *query = BoxQuery::recycled;
        return recycled_points(pa.box, pb.box, previous, previous_end, out);
      }
      if (refit_allowed(reuse.on, budget, stored_axis, motion.travelled)) {
        UninitializedArray<std::uint32_t, 4> ids;
        int n = 0;
        for (const SubContact* s = previous; s != previous_end && n < 4 && s->part_i == previous->part_i &&
                                             s->part_j == previous->part_j;
             ++s)
          ids[n++] = s->feature;
        ContactManifold refit;
        if (box_box_refit(pa.box, pb.box, ids.data(), n, refit)) {
          *query = BoxQuery::refit;
          return touching_points(refit, out);
        }
      }
      SatSource source = SatSource::stored_feature;
      const BoxBoxSat sat = lasting_box_sat(pa.box, pb.box, stored_axis, motion, reuse.on, budget, &source);
      if (source == SatSource::full) *query = BoxQuery::full;
      if (source == SatSource::apart_axis) *query = BoxQuery::apart_axis;
      if (sat.separated) {
        *gap = -sat.depth;
        return 0;
      }
      if (sat.axis >= 6) {
        // Edge against edge, most lasting contacts between crosses: the one point of
        // box_box_manifold, made here without the manifold.
        if (!(sat.depth > 0)) return 0;
        const ManifoldPoint q = box_box_edge_point(pa.box, pb.box, sat);
        out[0] = {sat.normal, q.point, q.delta_n, q.feature_id};
        if (reuse.on && reuse.recycle > 0) budget.allow_refit(motion.travelled, reuse.recycle);
        return 1;
      }
      const ContactManifold clipped = box_box_manifold(pa.box, pb.box, sat);
      // The approximation's margin (at most one is on): a travel, or a fraction of the overlap.
      if (reuse.on && (reuse.refit > 0 || reuse.recycle > 0))
        budget.allow_refit(motion.travelled, reuse.recycle > 0 ? reuse.recycle : reuse.refit * deepest(clipped));
      return touching_points(clipped, out);
    }
    return touching_points(
        contact_manifold(a.shape, part_pose(pa, a, body_a), b.shape, part_pose(pb, b, body_b), &warm), out);
  }
  // Two box cores run GJK on their placed axes; started cold (contact.gjk_warm_start = false)
  // they keep the posed shapes' path, whose rounding the runs made before the warm start had.
  const bool placed_cores = reuse.gjk_warm_start && pa.is_box && pb.is_box && a.shape.crust + b.shape.crust > 0;
  const PartContact c = placed_cores
                            ? crust_box_box_contact(core_box(pa, a), a.shape.crust, core_box(pb, b), b.shape.crust,
                                                    a.shape.bounding_radius + b.shape.bounding_radius, &warm)
                            : narrow_phase(a.shape, part_pose(pa, a, body_a), b.shape, part_pose(pb, b, body_b), &warm);
  if (!c.touching || !(c.delta_n > 0)) {
    // A negative overlap bounds the parts' distance from below (GJK's bound past its margin), so
    // the pair can sleep as the boxes' separating axes let it; without it every near part pair
    // ran GJK at every step.
    if (c.delta_n < 0) *gap = -c.delta_n;
    return 0;
  }
  out[0] = {c.normal, c.point, c.delta_n, warm.simplex};  // 0 unless kept
  return 1;
}

// Whether a part centred at `centre` and held in a ball of `reach` may touch an edge of the
// bounded wall: its ball's shadow on the wall's plane is not inside the rectangle.
bool reaches_an_edge(const Wall& wall, const Vec3& origin, const Vec3& centre, double reach) {
  const Vec3 q = centre - origin;
  return std::abs(dot(q, wall.axis_u)) + reach > wall.half_extent_u ||
         std::abs(dot(q, wall.axis_v)) + reach > wall.half_extent_v;
}

// Contact points of a part with a bounded wall near the wall's edges. The wall is a plate there,
// a sharp box behind its face as thick as the part is wide: a part reaching round an edge is
// pushed off the edge, its depth growing from zero as it comes over the face, where the
// plane's contact sets it in once and whole (the energy this gave a tetrapod sliding off a
// hopper's wall threw it out of the domain). Behind a face no thinner than the part, the
// shortest way out of the box is through that face or a side, never through the back.
int plate_points(const ConvexShape& part, const Pose& pose, const Wall& wall, const Vec3& origin, bool manifold,
                 PointGeometry out[4]) {
  const double thickness = 2 * part.bounding_radius;
  thread_local ConvexShape plate;
  plate = make_box({wall.half_extent_u, wall.half_extent_v, 0.5 * thickness});
  const Pose plate_pose{origin - 0.5 * thickness * wall.normal, Quat::from_frame(wall.axis_u, wall.axis_v, wall.normal)};
  if (manifold) return touching_points(contact_manifold(part, pose, plate, plate_pose), out);
  const PartContact c = narrow_phase(part, pose, plate, plate_pose);
  if (!c.touching || !(c.delta_n > 0)) return 0;
  out[0] = {c.normal, c.point, c.delta_n, 0};
  return 1;
}

// Finds the memory of a contact point in last step's list.
const SubContact* find_previous(std::span<const SubContact> previous, const SubContact& key) {
  for (const SubContact& s : previous)
    if (s.same_key(key)) return &s;
  return nullptr;
}

const SubContact* find_part_pair(std::span<const SubContact> previous, std::uint16_t a, std::uint16_t b) {
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

// Body-level cull: the 6 face axes of the two bodies' part-bounding boxes (Gottschalk et al.
// 1996). A separating face axis proves no part pair can touch; the separation along it, returned
// when positive, is a lower bound of the bodies' distance (0: no face axis separates).
double body_box_gap(const CompositeShape& si, const BodyFrame& bi, const CompositeShape& sj, const BodyFrame& bj) {
  const Vec3* A = bi.axis;
  const Vec3* B = bj.axis;
  const Vec3 d = bj.box_centre - bi.box_centre;
  const Vec3& ha = si.box_half;
  const Vec3& hb = sj.box_half;
  double absR[3][3];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) absR[i][j] = std::abs(dot(A[i], B[j]));
    const double gap = std::abs(dot(d, A[i])) - (ha[i] + hb[0] * absR[i][0] + hb[1] * absR[i][1] + hb[2] * absR[i][2]);
    if (gap > 0) return gap;
  }
  for (int j = 0; j < 3; ++j) {
    const double gap = std::abs(dot(d, B[j])) - (hb[j] + ha[0] * absR[0][j] + ha[1] * absR[1][j] + ha[2] * absR[2][j]);
    if (gap > 0) return gap;
  }
  return 0;
}

std::uint64_t ticks(bool on) { return on ? __rdtsc() : 0; }

// A row's travel plus the clock, raised by far more than the round-off of the two sums (each a
// sum over at most some 10^7 steps since the list was built, 2^-52 relative per term).
double wake_margin(double travel_and_clock) { return travel_and_clock * (1 + 1e-8); }

// Asks for the cache lines of [data, data + bytes), at most 8 of them.
void prefetch_lines(const void* data, std::size_t bytes) {
  const char* c = static_cast<const char*>(data);
  const std::size_t lines = std::min<std::size_t>((bytes + 63) / 64, 8);
  for (std::size_t k = 0; k < lines; ++k) __builtin_prefetch(c + 64 * k);
}

}  // namespace

template <TangentialModel Model, bool kProfile>
ContactResult World::composite_pair(std::size_t i, std::size_t j, std::span<const SubContact> previous,
                                    std::vector<SubContact>& contacts, double memory_dt, double travelled,
                                    PartBudget* part_budgets, double& gap) {
  gap = 0;
  constexpr bool profile = kProfile;  // the counters and clocks of the benchmark's profile, compiled out otherwise
  const std::uint64_t t_start = ticks(profile);
  std::uint64_t t_cull = 0, t_narrow = 0, t_force = 0, n_parts = 0, n_narrow = 0, n_points = 0, n_full = 0, n_reused = 0, n_refit = 0,
                n_recycled = 0, n_apart_axis = 0, n_touching = 0;
  const ParticleStore& p = particles_;
  thread_local CompositeShape scratch_i, scratch_j;
  const bool has_box_i = p.shape[i] != 0, has_box_j = p.shape[j] != 0;
  const CompositeShape& si = has_box_i ? shapes_[p.shape[i]] : shape_of(shapes_, 0, p.radius[i], scratch_i);
  const CompositeShape& sj = has_box_j ? shapes_[p.shape[j]] : shape_of(shapes_, 0, p.radius[j], scratch_j);
  // A sphere has no box and no entry in the placement cache: one part at its centre.
  UninitializedArray<PlacedPart, 1> sphere_i, sphere_j;
  if (!has_box_i) place_part(si.parts[0], {p.position[i], p.orientation[i]}, sphere_i[0]);
  if (!has_box_j) place_part(sj.parts[0], {p.position[j], p.orientation[j]}, sphere_j[0]);
  const PlacedPart* placed_i = has_box_i ? shaped_.placed.parts(i) : sphere_i.data();
  const PlacedPart* placed_j = has_box_j ? shaped_.placed.parts(j) : sphere_j.data();
  // A pair that touched last step still touches, almost always: its body boxes are not tested
  // (the part budgets then give the gap if it has parted).
  if (has_box_i && has_box_j && previous.empty() &&
      (gap = body_box_gap(si, shaped_.placed.body(i), sj, shaped_.placed.body(j))) > 0) {
    if (profile) {
      CompositeStats& st = composite_stats_slot();
      ++st.body_pairs;
      st.total_ticks += ticks(profile) - t_start;
    }
    return {};
  }
  const ContactParams& params = table_.pair(p.species[i], p.species[j]);
  const double reduced_mass = 1.0 / (p.inv_mass[i] + p.inv_mass[j]);
  const double reduced_radius = p.radius[i] * p.radius[j] / (p.radius[i] + p.radius[j]);
  const ContactMotion motion{p.velocity[i], p.angular_velocity[i], p.velocity[j], p.angular_velocity[j]};
  // A body turning by theta moves a point at its bounding radius R by 2 R sin(theta / 2) >= 2 R theta / pi.
  const PairMotion pair_motion{travelled, 0.5 * std::numbers::pi / std::min(p.radius[i], p.radius[j])};
  const bool had_contacts = !previous.empty();
  const bool one_point = !settings_.contact_manifold;
  const Reuse reuse{settings_.narrow_phase_reuse, settings_.manifold_refit, settings_.gjk_warm_start,
                    settings_.manifold_recycle};
  const bool anchored = settings_.contact_manifold && reuse.on && reuse.recycle > 0;
  const std::size_t first = contacts.size();

  ContactResult total;
  double least_gap = std::numeric_limits<double>::infinity();  // over the part pairs, while all are apart
  std::uint64_t t0 = ticks(profile);
  const std::size_t ni = si.parts.size(), nj = sj.parts.size();
  for (std::size_t a = 0; a < ni; ++a) {
    const PlacedPart& pa = placed_i[a];
    for (std::size_t b = 0; b < nj; ++b) {
      // Found apart by more than the two bodies have moved since: still apart, by at least
      // what is left of the budget.
      PartBudget& budget = part_budgets[a * nj + b];
      if (budget.asleep(travelled)) {
        least_gap = std::min(least_gap, budget.until - travelled);
        continue;
      }
      const PlacedPart& pb = placed_j[b];
      ++n_parts;
      const CompositePart &shape_a = si.parts[a], &shape_b = sj.parts[b];
      const auto part_a = static_cast<std::uint16_t>(a), part_b = static_cast<std::uint16_t>(b);
      // A touching box pair whose stored feature is still good overlaps: its capsules need no test.
      // Nor does a pair that touched last step with one point per part pair: GJK, started from
      // that contact, answers in about one iteration whether it still touches.
      const SubContact* stored = nullptr;
      bool looked_up = false;
      if (had_contacts && (one_point || (reuse.on && budget.axis >= 0))) {
        stored = find_part_pair(previous, part_a, part_b);
        looked_up = true;
      }
      if (!(stored && (one_point || feature_reusable(budget, sat_axis_of(stored->feature), travelled)))) {
        const double d2 =
            segment_distance2(pa.box.centre, capsule_axis(pa, shape_a), pb.box.centre, capsule_axis(pb, shape_b));
        const double reach = shape_a.capsule.radius + shape_b.capsule.radius;
        if (d2 >= reach * reach) {
          const double capsule_gap = std::sqrt(d2) - reach;
          least_gap = std::min(least_gap, capsule_gap);
          budget.sleep(travelled, capsule_gap);
          continue;
        }
      }
      if (!looked_up && had_contacts) stored = find_part_pair(previous, part_a, part_b);
      ++n_narrow;
      const std::uint64_t t1 = ticks(profile);
      t_cull += t1 - t0;
      UninitializedArray<PointGeometry, 4> points;
      double part_gap = 0;
      BoxQuery query = BoxQuery::stored_feature;
      const int n = part_points(shape_a, pa, p.orientation[i], shape_b, pb, p.orientation[j], settings_.contact_manifold,
                                reuse, stored, previous.data() + previous.size(), pair_motion, budget, points.data(),
                                &part_gap, &query);
      if (profile && pa.is_box && pb.is_box && settings_.contact_manifold) {
        if (query == BoxQuery::apart_axis) ++n_apart_axis;
        else ++(query == BoxQuery::full ? n_full : n_reused);
        n_refit += query == BoxQuery::refit;
        n_recycled += query == BoxQuery::recycled;
        n_touching += n > 0;
      }
      least_gap = std::min(least_gap, n == 0 ? part_gap : 0.0);
      if (n == 0 && part_gap > 0) budget.sleep(travelled, part_gap, budget.separating_axis());
      const std::uint64_t t2 = ticks(profile);
      t_narrow += t2 - t1;
      for (int k = 0; k < n; ++k) {
        // Formed on the stack, every field set once, and appended whole: value-initialising the
        // record (a rep stos of 104 bytes, here or in the list) cost more than the copy.
        UninitializedArray<SubContact, 1> slot;
        SubContact& s = slot[0];
        s.part_i = part_a;
        s.part_j = part_b;
        s.feature = points[k].feature;
        // One point per part pair: its feature is GJK's simplex, which moves; the pair is the key.
        // A recycled point is its own record of last step.
        const SubContact* old = !had_contacts                   ? nullptr
                                : points[k].recycled         ? points[k].recycled
                                : settings_.contact_manifold ? find_previous(previous, s)
                                                              : stored;
        s.spring = old ? old->spring : Vec3{};
        s.normal_prev = old ? old->normal_prev : Vec3{};
        // A recycled point keeps the anchors it came from; a computed one is anchored afresh.
        if (anchored && pa.is_box && pb.is_box)
          s.anchors = points[k].recycled ? points[k].recycled->anchors
                                         : anchors_of(pa.box, pb.box, points[k].normal, points[k].point, points[k].overlap);
        apply_point<Model>(points[k], 1.0 / n, params, reduced_mass, reduced_radius, p.position[i], p.position[j], motion,
                           memory_dt, s, total);
        contacts.push_back(s);
      }
      n_points += static_cast<std::uint64_t>(n);
      t0 = ticks(profile);
      t_force += t0 - t2;
    }
  }
  if (contacts.size() == first && least_gap > 0 && least_gap < std::numeric_limits<double>::infinity()) gap = least_gap;
  if (profile) {
    const std::uint64_t t_end = ticks(profile);
    t_cull += t_end - t0;
    CompositeStats& st = composite_stats_slot();
    ++st.body_pairs;
    st.part_pairs += n_parts;
    st.narrow += n_narrow;
    st.points += n_points;
    st.box_full_queries += n_full;
    st.box_reused += n_reused;
    st.box_refit += n_refit;
    st.box_recycled += n_recycled;
    st.box_apart_axis += n_apart_axis;
    st.box_touching += n_touching;
    st.cull_ticks += t_cull;
    st.narrow_ticks += t_narrow;
    st.force_ticks += t_force;
    st.total_ticks += t_end - t_start;
  }
  return total;
}

template <TangentialModel Model>
ContactResult World::composite_wall(std::size_t i, const Wall& wall, const Vec3& origin, const Vec3& wall_velocity,
                                    std::span<const SubContact> previous, std::vector<SubContact>& contacts,
                                    double memory_dt) {
  const ParticleStore& p = particles_;
  thread_local CompositeShape scratch;
  const CompositeShape& si = shape_of(shapes_, p.shape[i], p.radius[i], scratch);
  const ContactParams& params = table_.wall(p.species[i], wall.material);
  const HalfSpace plane{wall.normal, dot(wall.normal, origin)};  // solid behind the wall, normal into the free side
  const ContactMotion motion{p.velocity[i], p.angular_velocity[i], wall_velocity, Vec3{}};
  ContactResult total;
  const PlacedPart* placed = shaped_.placed.parts(i);
  for (std::size_t a = 0; a < si.parts.size(); ++a) {
    // The part's bounding sphere clears the plane: no corner can touch it.
    if (dot(placed[a].box.centre, plane.normal) - plane.offset >= si.parts[a].shape.bounding_radius) continue;
    // A box's support along the normal clears the plane too (with a margin far above rounding,
    // so this skips nothing the corner test below would keep): most boxes near a wall are
    // tilted away from it.
    if (const PlacedPart& part = placed[a]; part.is_box) {
      const OrientedBox& box = part.box;
      const double reach = box.half.x * std::abs(dot(box.axis[0], plane.normal)) +
                           box.half.y * std::abs(dot(box.axis[1], plane.normal)) +
                           box.half.z * std::abs(dot(box.axis[2], plane.normal));
      if (dot(box.centre, plane.normal) - plane.offset - reach > 1e-9 * si.parts[a].shape.bounding_radius) continue;
    }
    const Pose pa = part_pose(placed[a], si.parts[a], p.orientation[i]);
    UninitializedArray<PointGeometry, 4> points;
    int n = 0;
    if (wall.bounded && reaches_an_edge(wall, origin, placed[a].box.centre, si.parts[a].shape.bounding_radius)) {
      n = plate_points(si.parts[a].shape, pa, wall, origin, settings_.contact_manifold, points.data());
    } else if (settings_.contact_manifold) {
      n = touching_points(
          convex_plane_manifold(si.parts[a].shape, pa, plane, placed[a].is_box ? &placed[a].box : nullptr),
          points.data());
    } else {
      const PartContact c = convex_plane_contact(si.parts[a].shape, pa, plane);
      if (c.touching && c.delta_n > 0) points[n++] = {c.normal, c.point, c.delta_n, 0};
    }
    for (int k = 0; k < n; ++k) {
      UninitializedArray<SubContact, 1> slot;  // every field set once, as in composite_pair
      SubContact& s = slot[0];
      s.part_i = static_cast<std::uint16_t>(a);
      s.part_j = 0;
      s.feature = points[k].feature;
      const SubContact* old = find_previous(previous, s);
      s.spring = old ? old->spring : Vec3{};
      s.normal_prev = old ? old->normal_prev : Vec3{};
      apply_point<Model>(points[k], 1.0 / n, params, 1.0 / p.inv_mass[i], p.radius[i], p.position[i], points[k].point,
                         motion, memory_dt, s, total);
      contacts.push_back(s);
    }
  }
  return total;
}

// Pairs of rigid bodies cost a culling stage and a narrow phase each, and a pile rarely spans
// enough slabs for the colouring of pair_forces to keep two threads busy. So rows are taken in
// blocks, each thread keeping its own run of blocks from step to step (block_schedule.h), each
// block recording what it adds to which body, binned by the body's range of indices. The ranges
// are then applied in parallel, each block by block: every body receives its contributions in
// the same order on any number of threads.
template <TangentialModel Model>
void World::composite_pair_forces(double memory_dt) {
  ScopedPhase phase(timer_, Phase::pair_forces);
  ParticleStore& p = particles_;
  PairList& list = lists_.pairs;
  ContactMemory& mem = list.memory;
  constexpr long kRowsPerBlock = SubContactStore::kRowsPerBlock;
  const long rows = static_cast<long>(list.rows());
  const long blocks = (rows + kRowsPerBlock - 1) / kRowsPerBlock;
  if (shaped_.block_loads.size() < static_cast<std::size_t>(blocks)) shaped_.block_loads.resize(blocks);
  if (!shaped_.budgets.matches(list)) {
    shaped_.budgets.reset(list, p, shapes_);
    shaped_.block_wake.clear();
  }
  if (shaped_.block_wake.size() != static_cast<std::size_t>(blocks)) shaped_.block_wake.assign(blocks, {});
  const double clock = shaped_.placed.travel_clock();
  shaped_.pair_points.follow(list);
  double* budget = shaped_.budgets.body();
  const std::size_t bodies = p.position.size();  // ghosts receive loads too (folded later)
  auto range_of = [bodies](std::uint32_t body) { return static_cast<std::size_t>(body) * ShapedContacts::kLoadRanges / bodies; };
  const int threads = worth_parallel(16 * p.owned) ? omp_get_max_threads() : 1;
  shaped_.block_schedule.plan(blocks, threads);
  const bool profiling = composite_stats_enabled();
#pragma omp parallel num_threads(threads)
  {
    const int thread = omp_get_thread_num();
    std::vector<std::uint32_t> awake;  // entries of the block's rows worth a look, in order
    std::array<std::uint32_t, kRowsPerBlock + 1> awake_start;  // per row of the block, into `awake`
    std::array<double, kRowsPerBlock> next_asleep_until{};     // ShapedContacts::BlockWake
    for (long block = 0; shaped_.block_schedule.next(thread, block);) {
      const std::uint64_t block_start = __rdtsc();
      ShapedContacts::BlockLoads& loads = shaped_.block_loads[block];
      for (std::vector<ShapedContacts::BodyLoad>& range : loads) range.clear();
      const long last = std::min(rows, (block + 1) * kRowsPerBlock);
      // What the awake pairs of the block will read first lies in scattered lines (the part-pair
      // budgets, the neighbour's placed parts): asking for them all at once lets the cache misses
      // overlap instead of stalling one pair at a time. Last step's contact points are one
      // stream per block (SubContactStore).
      // The awake entries (apart by less than both bodies can have moved since the gap was
      // measured, or touching) are gathered here, so that the pass below visits only them.
      const long first_row = block * kRowsPerBlock;
      ShapedContacts::BlockWake& last_pass = shaped_.block_wake[block];
      awake.clear();
      for (long row = first_row; row < last; ++row) {
        const auto i = static_cast<std::uint32_t>(row);
        const std::size_t r = static_cast<std::size_t>(row - first_row);
        awake_start[r] = static_cast<std::uint32_t>(awake.size());
        const double travel_i = shaped_.placed.travel(i);
        const auto wake = [&](std::uint32_t e) {
          const std::uint32_t j = list.neighbor(e);
          awake.push_back(e);
          shaped_.budgets.prefetch_parts(e);
          if (p.shape[j] != 0)  // the two lines of every part
            prefetch_lines(shaped_.placed.parts(j), shaped_.placed.part_count(j) * sizeof(PlacedPart));
        };
        // Entry e sleeps while travel_i + travel_j < budget[e]. Since the last full test of the
        // row, travel_j has grown by no more than the clock has: the sleepers found then stay
        // asleep while travel_i + clock < min(budget[e] - travel_j then) + clock then. The
        // margin covers the round-off of the travels' and the clock's sums.
        if (last_pass.valid && wake_margin(travel_i + clock) < last_pass.asleep_until[r]) {
          double asleep_until = last_pass.asleep_until[r];
          for (std::uint32_t k = last_pass.start[r]; k < last_pass.start[r + 1]; ++k) {
            const std::uint32_t e = last_pass.awake[k];
            const double travel_j = shaped_.placed.travel(list.neighbor(e));
            if (travel_i + travel_j < budget[e]) asleep_until = std::min(asleep_until, budget[e] - travel_j + clock);
            else wake(e);
          }
          next_asleep_until[r] = asleep_until;
          continue;
        }
        double asleep_until = std::numeric_limits<double>::infinity();
        std::uint32_t e = list.row_begin(i);
        const std::uint32_t row_end = list.row_end(i);
#ifdef TALUS_COMPOSITE_AVX2
        // Four entries per test (a cross lists some 37 neighbours, one in ten awake).
        const __m256d travel_i4 = _mm256_set1_pd(travel_i);
        __m256d until4 = _mm256_set1_pd(asleep_until);
        for (; e + 4 <= row_end; e += 4) {
          const __m128i j4 = _mm_loadu_si128(reinterpret_cast<const __m128i*>(list.neighbors() + e));
          const __m256d travel_j = _mm256_mask_i32gather_pd(_mm256_setzero_pd(), shaped_.placed.travels(), j4,
                                                            _mm256_castsi256_pd(_mm256_set1_epi64x(-1)), 8);
          const __m256d travelled = _mm256_add_pd(travel_i4, travel_j);
          const __m256d budget4 = _mm256_loadu_pd(budget + e);
          // Awake unless travelled < budget, exactly as the scalar test (NaN stays awake).
          const __m256d awake4 = _mm256_cmp_pd(travelled, budget4, _CMP_NLT_UQ);
          const __m256d until_e = _mm256_add_pd(_mm256_sub_pd(budget4, travel_j), _mm256_set1_pd(clock));
          until4 = _mm256_min_pd(until4, _mm256_blendv_pd(until_e, _mm256_set1_pd(asleep_until), awake4));
          int wakes = _mm256_movemask_pd(awake4);
          for (; wakes; wakes &= wakes - 1) wake(e + static_cast<std::uint32_t>(__builtin_ctz(wakes)));
        }
        alignas(32) double until_lanes[4];
        _mm256_store_pd(until_lanes, until4);
        for (double u : until_lanes) asleep_until = std::min(asleep_until, u);
#endif
        for (; e < row_end; ++e) {
          const double travel_j = shaped_.placed.travel(list.neighbor(e));
          if (travel_i + travel_j < budget[e]) asleep_until = std::min(asleep_until, budget[e] - travel_j + clock);
          else wake(e);
        }
        next_asleep_until[r] = asleep_until;
      }
      awake_start[last - first_row] = static_cast<std::uint32_t>(awake.size());
      shaped_.pair_points.start_block(block);
      std::vector<SubContact>& points = shaped_.pair_points.next_points(block);
      for (long row = first_row; row < last; ++row) {
        const auto i = static_cast<std::uint32_t>(row);
        Vec3 fi, ti;
        for (std::uint32_t k = awake_start[row - first_row]; k < awake_start[row - first_row + 1]; ++k) {
          const std::uint32_t e = awake[k];
          const std::uint32_t j = list.neighbor(e);
          const double travelled = shaped_.placed.travel(i) + shaped_.placed.travel(j);
          const Vec3 d = p.position[i] - p.position[j];
          const double reach = p.radius[i] + p.radius[j];
          const double dist2 = norm2(d);
          if (dist2 >= reach * reach) {  // bounding spheres apart: a later contact starts afresh
            shaped_.pair_points.forget(block, e);
            if (mem.active(e)) mem.clear(e);
            budget[e] = travelled + (std::sqrt(dist2) - reach);
            continue;
          }
          ContactResult r;
          if (p.shape[i] != 0 || p.shape[j] != 0) {
            double gap = 0;
            const std::size_t first = points.size();
            r = profiling ? composite_pair<Model, true>(i, j, shaped_.pair_points.take(block, e), points, memory_dt,
                                                        travelled, shaped_.budgets.parts(e), gap)
                          : composite_pair<Model, false>(i, j, shaped_.pair_points.take(block, e), points, memory_dt,
                                                         travelled, shaped_.budgets.parts(e), gap);
            shaped_.pair_points.record(e, first, points.size());
            if (points.size() == first) {
              budget[e] = travelled + gap;
              continue;
            }
          } else {
            const ContactMotion m{p.velocity[i], p.angular_velocity[i], p.velocity[j], p.angular_velocity[j]};
            r = sphere_contact<Model>(d, dist2, p.radius[i], p.radius[j], m, table_.pair(p.species[i], p.species[j]),
                                      1.0 / (p.inv_mass[i] + p.inv_mass[j]), memory_dt, memory_ref(mem, e));
          }
          fi += r.force_on_i;
          ti += r.torque_i;
          loads[range_of(j)].push_back({j, -r.force_on_i, r.torque_j});
        }
        if (fi != Vec3{} || ti != Vec3{}) loads[range_of(i)].push_back({i, fi, ti});
      }
      shaped_.pair_points.finish_block(block);
      // This pass's awake entries are the next pass's to test again; its buffer is recycled.
      std::swap(last_pass.awake, awake);
      std::copy(awake_start.begin(), awake_start.end(), last_pass.start.begin());
      last_pass.asleep_until = next_asleep_until;
      last_pass.valid = true;
      shaped_.block_schedule.record(block, __rdtsc() - block_start);
    }
#pragma omp barrier
#pragma omp for schedule(static)
    for (int range = 0; range < ShapedContacts::kLoadRanges; ++range)
      for (long block = 0; block < blocks; ++block)
        for (const ShapedContacts::BodyLoad& l : shaped_.block_loads[block][range]) {
          p.force[l.body] += l.force;
          p.torque[l.body] += l.torque;
        }
  }
}

#define TALUS_INSTANTIATE(M)                                                                                    \
  template ContactResult World::composite_pair<M, true>(std::size_t, std::size_t, std::span<const SubContact>,    \
                                                        std::vector<SubContact>&, double, double, PartBudget*, double&); \
  template ContactResult World::composite_pair<M, false>(std::size_t, std::size_t, std::span<const SubContact>,   \
                                                  std::vector<SubContact>&, double, double, PartBudget*, double&); \
  template ContactResult World::composite_wall<M>(std::size_t, const Wall&, const Vec3&, const Vec3&,             \
                                                  std::span<const SubContact>, std::vector<SubContact>&, double);  \
  template void World::composite_pair_forces<M>(double);
TALUS_INSTANTIATE(TangentialModel::memory)
TALUS_INSTANTIATE(TangentialModel::elastic_spring)
TALUS_INSTANTIATE(TangentialModel::memoryless)
#undef TALUS_INSTANTIATE

}  // namespace talus
