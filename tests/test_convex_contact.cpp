// Narrow phase against brute force: random boxes and polyhedra (crust GJK/EPA and box SAT),
// degenerate placements, plane contact, manifolds and stable feature ids.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <set>

#include "talus/collide/box_box.h"
#include "talus/collide/convex_contact.h"
#include "talus/collide/convex_contact_analytic.h"
#include "talus/collide/gjk_epa.h"
#include "talus/collide/manifold.h"
#include "talus/shape/composite_shape.h"
#include "talus/shape/convex_hull.h"
#include "talus/shape/convex_shape.h"

namespace talus {
namespace {

constexpr double kPi = std::numbers::pi;

std::vector<Vec3> core_vertices(const ConvexShape& s, const Pose& p) {
  std::vector<Vec3> v;
  if (const Box* b = std::get_if<Box>(&s.core)) {
    const Vec3 h = b->half_extents;
    for (int k = 0; k < 8; ++k) v.push_back(p.to_parent({k & 1 ? h.x : -h.x, k & 2 ? h.y : -h.y, k & 4 ? h.z : -h.z}));
  } else {
    for (const Vec3& x : std::get<ConvexPolyhedron>(s.core).hull.vertices) v.push_back(p.to_parent(x));
    // Erosion leaves near-duplicate vertices where several faces meet; they only slow the hull.
  }
  return v;
}

Vec3 closest_on_segment(const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double t = std::clamp(-dot(a, ab) / norm2(ab), 0.0, 1.0);
  return a + ab * t;
}

// Reference, independent of GJK/EPA: the Minkowski difference of the cores built explicitly as
// the hull of all vertex differences; signed distance of the origin to it, minus both crusts.
struct Reference {
  double overlap;
  Vec3 normal;  // from B to A
};
Reference brute_force(const ConvexShape& a, const Pose& pa, const ConvexShape& b, const Pose& pb) {
  std::vector<Vec3> diff;
  for (const Vec3& x : core_vertices(a, pa))
    for (const Vec3& y : core_vertices(b, pb)) diff.push_back(x - y);
  const ConvexHull d = build_convex_hull(diff);
  const double crusts = a.crust + b.crust;
  double min_offset = 1e300;
  Vec3 face_normal;
  for (const HullFace& f : d.faces)
    if (f.offset < min_offset) min_offset = f.offset, face_normal = f.normal;
  if (min_offset >= 0) return {min_offset + crusts, -face_normal};  // origin inside
  Vec3 best{1e300, 0, 0};
  for (const auto& t : d.triangles) {
    const Vec3 p0 = d.vertices[t[0]], p1 = d.vertices[t[1]], p2 = d.vertices[t[2]];
    const Vec3 n = normalized_or_zero(cross(p1 - p0, p2 - p0));
    const Vec3 q = n * dot(n, p0);  // projection of the origin on the plane
    const bool inside = dot(cross(p1 - p0, q - p0), n) >= 0 && dot(cross(p2 - p1, q - p1), n) >= 0 &&
                        dot(cross(p0 - p2, q - p2), n) >= 0;
    for (const Vec3& c : {inside ? q : best, closest_on_segment(p0, p1), closest_on_segment(p1, p2),
                          closest_on_segment(p2, p0)})
      if (norm2(c) < norm2(best)) best = c;
  }
  return {crusts - norm(best), normalized_or_zero(best)};
}

Quat random_quat(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  return Quat{g(rng), g(rng), g(rng), g(rng)}.normalized();
}

ConvexShape random_polyhedron(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u(0.5, 1.5);
  const Vec3 axes{u(rng), u(rng), u(rng)};
  std::vector<Vec3> pts = {{axes.x, 0, 0}, {-axes.x, 0, 0}, {0, axes.y, 0}, {0, -axes.y, 0}, {0, 0, axes.z}, {0, 0, -axes.z}};
  for (int i = 0; i < 12; ++i) pts.push_back(hadamard(normalized_or_zero({g(rng), g(rng), g(rng)}), axes));
  return make_polyhedron(pts, 0.08);
}

ConvexShape random_box(std::mt19937_64& rng, bool sharp) {
  std::uniform_real_distribution<double> u(0.3, 1.5);
  const Vec3 h{u(rng), u(rng), u(rng)};
  return make_box(h, sharp ? 0.0 : 0.15 * std::min({h.x, h.y, h.z}));
}

// Shape-independent consistency: finite, unit normal, point_a on A's contact surface along -n,
// point_b on B's along +n, and point_a - point_b = -delta_n n.
void expect_consistent(const PartContact& g, const ConvexShape& a, const Pose& pa, const ConvexShape& b,
                       const Pose& pb, double tol, bool sharp = false) {
  ASSERT_TRUE(std::isfinite(g.delta_n) && std::isfinite(g.point.x) && std::isfinite(g.normal.z));
  EXPECT_NEAR(norm(g.normal), 1, 1e-9);
  const PosedSupport sa{sharp ? &a.geometry : &a.core, pa, sharp ? 0.0 : a.crust};
  const PosedSupport sb{sharp ? &b.geometry : &b.core, pb, sharp ? 0.0 : b.crust};
  EXPECT_NEAR(dot(g.normal, g.point_a), dot(g.normal, sa.support(-g.normal)), tol);
  EXPECT_NEAR(dot(g.normal, g.point_b), dot(g.normal, sb.support(g.normal)), tol);
  EXPECT_NEAR(dot(g.normal, g.point_b - g.point_a), g.delta_n, tol);
  EXPECT_NEAR(norm(g.point - (g.point_a + g.point_b) * 0.5), 0, 1e-12);
}

struct Tally {
  int none = 0, crust = 0, deep = 0, fallback = 0, bad_reference = 0;
  double worst_depth = 0, worst_normal = 0;
  double worst_epa_depth = 0, worst_epa_normal = 0;  ///< over the pairs EPA answered
};

// Brief (b): random pairs; depth and normal within 1 % of depth, no missed or false contacts.
void random_pairs(const char* name, int trials, unsigned seed, auto make_a, auto make_b, auto query, bool sharp) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> g;
  Tally t;
  for (int trial = 0; trial < trials; ++trial) {
    const ConvexShape a = make_a(rng), b = make_b(rng);
    const Pose pa{{u(rng), u(rng), u(rng)}, random_quat(rng)};
    const double reach = a.bounding_radius + b.bounding_radius;
    const Pose pb{pa.position + normalized_or_zero({g(rng), g(rng), g(rng)}) * (reach * (0.35 + 0.7 * u(rng))),
                  random_quat(rng)};
    const Reference ref = brute_force(a, pa, b, pb);
    const PartContact c = query(a, pa, b, pb);
    ASSERT_TRUE(std::isfinite(c.delta_n) && std::isfinite(c.normal.x) && std::isfinite(c.point.x));
    const double tiny = 1e-9 * reach;
    if (ref.overlap < -tiny) {
      EXPECT_FALSE(c.touching) << name << " false contact, trial " << trial;
      ++t.none;
      continue;
    }
    if (ref.overlap <= tiny) continue;  // touching within rounding: either answer is right
    {  // The reference must be self-consistent: its overlap is the one along its own normal.
      const PosedSupport sa{sharp ? &a.geometry : &a.core, pa, sharp ? 0.0 : a.crust};
      const PosedSupport sb{sharp ? &b.geometry : &b.core, pb, sharp ? 0.0 : b.crust};
      if (std::abs(dot(sb.support(ref.normal) - sa.support(-ref.normal), ref.normal) - ref.overlap) >
          1e-3 * ref.overlap) {
        ++t.bad_reference;
        continue;
      }
    }
    ASSERT_TRUE(c.touching) << name << " missed contact, trial " << trial << " ref overlap " << ref.overlap;
    t.crust += c.method == ContactMethod::kCrustGjk;
    t.deep += c.method == ContactMethod::kCrustEpa;
    t.fallback += c.method == ContactMethod::kFallback;
    const double ed = std::abs(c.delta_n - ref.overlap) / ref.overlap, en = norm(c.normal - ref.normal);
    t.worst_depth = std::max(t.worst_depth, ed);
    t.worst_normal = std::max(t.worst_normal, en);
    if (c.method == ContactMethod::kCrustEpa) {
      t.worst_epa_depth = std::max(t.worst_epa_depth, ed);
      t.worst_epa_normal = std::max(t.worst_epa_normal, en);
    }
    if (ed > 0.01 || en > 0.01) {  // diagnose: overlap measured along each normal by the supports
      const PosedSupport sa{&a.core, pa, a.crust}, sb{&b.core, pb, b.crust};
      auto along = [&](const Vec3& n) { return dot(sb.support(n) - sa.support(-n), n); };
      ADD_FAILURE() << name << " trial " << trial << " method " << int(c.method) << " depth " << c.delta_n
                    << " ref " << ref.overlap << " along(n) " << along(c.normal) << " along(ref) " << along(ref.normal);
    }
    EXPECT_LE(ed, 0.01) << name << " trial " << trial;
    EXPECT_LE(en, 0.01) << name << " trial " << trial;
    expect_consistent(c, a, pa, b, pb, 1e-7 * reach, sharp);
  }
  std::printf("%s: %d pairs, none %d, crust-GJK %d, core-EPA %d, fallback %d, bad reference %d; worst rel depth err "
              "%.1e, normal err %.1e (EPA alone: %.1e, %.1e)\n",
              name, trials, t.none, t.crust, t.deep, t.fallback, t.bad_reference, t.worst_depth, t.worst_normal,
              t.worst_epa_depth, t.worst_epa_normal);
  EXPECT_LE(t.bad_reference, trials / 50);
}

TEST(ConvexContact, RandomBoxesCrustVsBruteForce) {
  random_pairs("box-box crust", 3000, 11, [](auto& r) { return random_box(r, false); },
               [](auto& r) { return random_box(r, false); },
               [](auto&... x) { return crust_contact(x...); }, false);
}

TEST(ConvexContact, RandomSharpBoxesSatVsBruteForce) {
  random_pairs("box-box SAT", 3000, 12, [](auto& r) { return random_box(r, true); },
               [](auto& r) { return random_box(r, true); },
               [](auto&... x) { return narrow_phase(x...); }, true);
}

// The brute-force reference builds the hull of ~3500 vertex differences per pair (qhull: 2.3 s
// for the 130 pairs).
TEST(ConvexContact, RandomPolyhedraVsBruteForce) {
  random_pairs("poly-poly crust", 70, 13, random_polyhedron, random_polyhedron,
               [](auto&... x) { return narrow_phase(x...); }, false);
  random_pairs("poly-box crust", 60, 14, random_polyhedron, [](auto& r) { return random_box(r, false); },
               [](auto&... x) { return narrow_phase(x...); }, false);
}

// The insertion's yes-or-no test gives narrow_phase's answer to delta_n > -clearance, without
// EPA, for polyhedra, cylinders, rounded and sharp boxes and spheres, at every distance.
TEST(ConvexContact, PartsWithinAgreesWithTheNarrowPhase) {
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> g;
  const auto random_part = [&](int kind) {
    switch (kind) {
      case 0: return random_polyhedron(rng);
      case 1: return make_cylinder(0.3 + 0.5 * u(rng), 0.3 + 0.7 * u(rng), 0.05);
      case 2: return random_box(rng, false);
      case 3: return random_box(rng, true);
      default: return make_sphere(0.3 + 0.5 * u(rng));
    }
  };
  int inside = 0, apart = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const ConvexShape a = random_part(trial % 5), b = random_part((trial / 5) % 5);
    const Pose pa{{u(rng), u(rng), u(rng)}, random_quat(rng)};
    const double reach = a.bounding_radius + b.bounding_radius;
    const Pose pb{pa.position + normalized_or_zero({g(rng), g(rng), g(rng)}) * (reach * (0.2 + 0.9 * u(rng))),
                  random_quat(rng)};
    const double clearance = 0.01 * reach * u(rng);
    for (const bool sharp : {false, true}) {
      const PartContact c = narrow_phase(a, pa, b, pb, nullptr, NarrowPhaseOptions{sharp});
      // On the edge either answer is right. Between -clearance and 0 the crust method's delta_n
      // is only a bound (GJK stops once the cores are a crust apart), so it decides nothing.
      if (c.delta_n > -clearance - 1e-9 * reach && c.delta_n < 1e-9 * reach) continue;
      const bool expected = c.delta_n > -clearance;
      ASSERT_EQ(parts_within(a, pa, b, pb, clearance, NarrowPhaseOptions{sharp}), expected)
          << "trial " << trial << " kinds " << trial % 5 << ", " << (trial / 5) % 5 << " delta_n " << c.delta_n;
      (expected ? inside : apart) += 1;
    }
  }
  EXPECT_GT(inside, 200);  // both answers are well represented
  EXPECT_GT(apart, 200);
}

// A ball against a rounded cylinder in closed form: outside the core the GJK crust method is
// exact (its core distance) and must agree; inside, the depth is that of the nearer face. The
// case that broke EPA down (a ball's centre deep in a cylinder core, a tetrapod's hub in an arm)
// now gets its closed-form depth, and EPA alone gives up (ok = false) instead of multiplying faces.
TEST(ConvexContact, SphereAgainstCylinderInClosedForm) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> g;
  int outside = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const ConvexShape ball = make_sphere(0.2 + 0.5 * u(rng)), cyl = make_cylinder(0.3 + 0.5 * u(rng), 0.3 + 0.7 * u(rng), 0.05);
    const Pose pb{{u(rng), u(rng), u(rng)}, random_quat(rng)};
    const Pose pa{pb.position + normalized_or_zero({g(rng), g(rng), g(rng)}) * (1.6 * u(rng)), Quat{}};
    const PartContact c = narrow_phase(ball, pa, cyl, pb);
    ASSERT_EQ(c.method, ContactMethod::kSphereCylinder);
    const PartContact flipped = narrow_phase(cyl, pb, ball, pa);
    EXPECT_NEAR(flipped.delta_n, c.delta_n, 1e-15);
    EXPECT_NEAR(norm(flipped.normal + c.normal), 0, 1e-12);
    const Cylinder& core = std::get<Cylinder>(cyl.core);
    const Vec3 q = pb.to_child(pa.position);
    const double rho = std::hypot(q.x, q.y);
    if (rho < core.radius && std::abs(q.z) < core.half_height) {  // centre inside the core
      const double depth = std::min(core.radius - rho, core.half_height - std::abs(q.z));
      EXPECT_NEAR(c.delta_n, ball.crust + cyl.crust + depth, 1e-12);
      continue;
    }
    const PartContact reference = crust_contact(ball, pa, cyl, pb);
    if (reference.method != ContactMethod::kCrustGjk || !reference.touching) continue;
    ++outside;
    EXPECT_NEAR(c.delta_n, reference.delta_n, 1e-9);
    EXPECT_NEAR(norm(c.normal - reference.normal), 0, 1e-6);
    EXPECT_NEAR(norm(c.point_b - reference.point_b), 0, 1e-6);
  }
  EXPECT_GT(outside, 50);

  const ConvexShape hub = make_sphere(0.54789632196434424), arm = make_cylinder(0.64279281493331681, 0.83825214329726112, 0.05);
  const Pose ph{{0.73831085875613001, 0.64079322383093396, 0.63611376880280801},
                Quat{-0.31857199601630914, 0.2893646898092927, 0.47177355286421596, 0.76955160610814877}};
  const Pose pc{{0.90530926275071888, 0.78824829369240668, -0.066889941039236511},
                Quat{0.033081740756416962, -0.95730771111420254, -0.16985172496636855, 0.23155547109874308}};
  const PosedSupport sh{&hub.core, ph, 0.0}, sc{&arm.core, pc, 0.0};
  GjkOptions opt;
  opt.scale = hub.bounding_radius + arm.bounding_radius;
  const GjkResult r = gjk_distance(sh, sc, opt);
  ASSERT_TRUE(r.intersecting);
  const EpaResult e = epa_penetration(sh, sc, r.simplex, opt.scale);
  EXPECT_LE(e.iterations, 128);
  const Vec3 q = pc.to_child(ph.position);
  const double depth = std::min(0.59279281493331681 - std::hypot(q.x, q.y), 0.78825214329726112 - std::abs(q.z));
  if (e.ok) EXPECT_NEAR(e.depth, depth, 1e-6 * opt.scale);  // EPA, when it answers, is right
  EXPECT_NEAR(narrow_phase(hub, ph, arm, pc).delta_n, hub.crust + arm.crust + depth, 1e-12);
}

// Brief (c): degenerate placements, for the crust path and for SAT.
TEST(ConvexContact, DegenerateCasesNoNaN) {
  const ConvexShape cube = make_box({1, 1, 1}, 0.1), sharp = make_box({1, 1, 1});
  const Quat edge_x = Quat::from_axis_angle({1, 0, 0}, kPi / 4), edge_y = Quat::from_axis_angle({0, 1, 0}, kPi / 4);
  // Corner down: rotate the diagonal (1,1,1) onto -z.
  const Quat corner = Quat::from_axis_angle(cross(normalized_or_zero({1, 1, 1}), {0, 0, -1}),
                                            std::acos(-1 / std::sqrt(3.0)));
  const double s2 = std::sqrt(2.0), s3 = std::sqrt(3.0);
  struct Case {
    const char* name;
    Pose pa;        // B is the identity-pose cube at the origin, A on top unless stated
    Pose pb;
    double depth;   // expected overlap
  };
  for (double d : {0.0, 1e-9, 0.05, 0.2, 0.5}) {  // 0.2 = both crusts exactly; 0.5 beyond
    const std::vector<Case> cases = {
        {"face on face", Pose{{0, 0, 2 - d}, {}}, Pose{}, d},
        {"face on face shifted", Pose{{0.7, -0.4, 2 - d}, {}}, Pose{}, d},
        {"edge on face", Pose{{0.3, 0, 1 + s2 - d}, edge_x}, Pose{}, d},
        {"edge on edge", Pose{{0, 0, 2 * s2 - d}, edge_x}, Pose{{}, edge_y}, d},
        {"vertex on face", Pose{{0.2, 0.1, 1 + s3 - d}, corner}, Pose{}, d},
        {"stacked parallel, big on small", Pose{{0, 0, 2 - d}, {}}, Pose{}, d},
    };
    for (const Case& c : cases) {
      for (const ConvexShape* s : {&cube, &sharp}) {
        const PartContact g = narrow_phase(*s, c.pa, *s, c.pb);
        SCOPED_TRACE(std::string(c.name) + (s == &cube ? " crust" : " sharp") + " d=" + std::to_string(d));
        ASSERT_TRUE(std::isfinite(g.delta_n) && std::isfinite(g.normal.x) && std::isfinite(g.point.x));
        // The rounded edges of the crust shape sit lower than sharp ones by c (sqrt2 - 1) or c (sqrt3 - 1).
        double expect = c.depth;
        if (s == &cube && std::string(c.name) == "edge on face") expect -= 0.1 * (s2 - 1);
        if (s == &cube && std::string(c.name) == "edge on edge") expect -= 0.2 * (s2 - 1);
        if (s == &cube && std::string(c.name) == "vertex on face") expect -= 0.1 * (s3 - 1);
        if (expect < 1e-12 && !g.touching) continue;  // separated: delta_n is only a bound
        EXPECT_NEAR(g.delta_n, expect, 1e-9);
        EXPECT_NEAR(g.normal.z, 1, 1e-6);
        if (expect > 0) expect_consistent(g, *s, c.pa, *s, c.pb, 1e-8, s == &sharp);
      }
    }
  }
}

TEST(ConvexContact, AnalyticSphereBoxAndPlane) {
  const ConvexShape box = make_box({1, 2, 3}, 0.2), ball = make_sphere(0.5);
  const Pose pb{{0.1, 0.2, 0.3}, Quat::from_axis_angle({1, 2, 3}, 0.4)};
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-3, 3);
  for (int i = 0; i < 500; ++i) {
    const Pose ps{{u(rng), u(rng), u(rng)}, {}};
    const PartContact an = narrow_phase(ball, ps, box, pb);
    const PartContact gj = crust_contact(ball, ps, box, pb);
    ASSERT_EQ(an.touching, gj.touching);
    if (!an.touching) continue;
    EXPECT_NEAR(an.delta_n, gj.delta_n, 1e-6);
    EXPECT_NEAR(norm(an.normal - gj.normal), 0, 1e-5);
    const PartContact flipped = narrow_phase(box, pb, ball, ps);
    EXPECT_NEAR(norm(flipped.normal + an.normal), 0, 1e-15);
  }
  const HalfSpace floor{{0, 0, 1}, 0};
  const PartContact p = convex_plane_contact(box, Pose{{0, 0, 0.9}, {}}, floor);
  EXPECT_NEAR(p.delta_n, 2.1, 1e-12);
  EXPECT_NEAR(p.point_b.z, 0, 1e-12);
}

// Brief (d): a cube face-down on a plane: 4 corner points of equal depth; tilted about an edge: 2.
TEST(ConvexContactManifold, CubeOnPlane) {
  const ConvexShape cube = make_box({0.5, 0.5, 0.5}, 0.05);
  const HalfSpace floor{{0, 0, 1}, 0};
  const ContactManifold m = convex_plane_manifold(cube, Pose{{1, 2, 0.49}, {}}, floor);
  ASSERT_EQ(m.count, 4);
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(m.points[k].delta_n, 0.01, 1e-12);
    EXPECT_NEAR(std::abs(m.points[k].point_a.x - 1), 0.5, 1e-12);
    EXPECT_NEAR(std::abs(m.points[k].point_a.y - 2), 0.5, 1e-12);
  }
  const Quat tilt = Quat::from_axis_angle({1, 0, 0}, 0.2);
  const double low = 0.5 * (std::cos(0.2) + std::sin(0.2));  // height of the lowest edge below the centre
  const ContactManifold e = convex_plane_manifold(cube, Pose{{0, 0, low - 0.01}, tilt}, floor);
  ASSERT_EQ(e.count, 2);
  EXPECT_NEAR(e.points[0].delta_n, 0.01, 1e-12);
  EXPECT_NEAR(e.points[1].delta_n, 0.01, 1e-12);
  EXPECT_NEAR(std::abs(e.points[0].point_a.x - e.points[1].point_a.x), 1, 1e-12);
}

// The wall path passes the placed box so corners clearly above the plane are skipped: the
// manifold must not change by a bit. Boxes of a cross arm's proportions at random orientations,
// their centres from well inside the plane to just out of reach.
TEST(ConvexContactManifold, PlacedBoxSkipsOnlyCornersAbovePlane) {
  const Vec3 half{0.0135, 0.001, 0.0015};
  const ConvexShape arm = make_box(half);
  const HalfSpace floor{{0, 0, 1}, 0.02};
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  int touching = 0, skipped = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    Quat q{u(rng), u(rng), u(rng), u(rng)};
    q = q.normalized();
    const Pose pose{{0.3 + u(rng), 0.1 * u(rng), floor.offset + 0.014 * u(rng)}, q};
    const ContactManifold full = convex_plane_manifold(arm, pose, floor);
    const OrientedBox placed = oriented_box(half, pose);
    const ContactManifold culled = convex_plane_manifold(arm, pose, floor, &placed);
    ASSERT_EQ(full.count, culled.count) << "trial " << trial;
    for (int k = 0; k < full.count; ++k) {
      EXPECT_EQ(full.points[k].feature_id, culled.points[k].feature_id);
      EXPECT_EQ(full.points[k].delta_n, culled.points[k].delta_n);
      EXPECT_EQ(full.points[k].point, culled.points[k].point);
    }
    touching += full.count > 0;
    // How many corners the bound proves above the plane (it must prove some, or it does nothing).
    for (int k = 0; k < 8; ++k) {
      const Vec3 x = pose.to_parent({k & 1 ? half.x : -half.x, k & 2 ? half.y : -half.y, k & 4 ? half.z : -half.z});
      skipped += floor.offset - dot(floor.normal, x) < -1e-6;
    }
  }
  EXPECT_GT(touching, 2000);
  EXPECT_GT(skipped, 20000);
}

TEST(ConvexContactManifold, BoxOnBoxFaceAndEdge) {
  const ConvexShape big = make_box({2, 2, 0.5}), small = make_box({0.5, 0.5, 0.5});
  // Face on face: 4 points at the small box's bottom corners, equal depth.
  ContactManifold m = contact_manifold(small, Pose{{0.3, 0.2, 0.99}, {}}, big, Pose{});
  ASSERT_EQ(m.count, 4);
  for (int k = 0; k < m.count; ++k) EXPECT_NEAR(m.points[k].delta_n, 0.01, 1e-12);
  EXPECT_NEAR(m.normal.z, 1, 1e-12);
  // Same-size cubes twisted 45 deg: the clip is an octagon, reduced to 4 points.
  const ConvexShape cube = make_box({1, 1, 1});
  m = contact_manifold(cube, Pose{{0, 0, 1.98}, Quat::from_axis_angle({0, 0, 1}, kPi / 4)}, cube, Pose{});
  ASSERT_EQ(m.count, 4);
  for (int k = 0; k < m.count; ++k) EXPECT_NEAR(m.points[k].delta_n, 0.02, 1e-12);
  // Tilted about one edge: 2 points, and the single-point C is their midpoint.
  const Pose tilted{{0.2, 0.1, 0.5 + 0.5 * (std::cos(0.3) + std::sin(0.3)) - 0.01},
                    Quat::from_axis_angle({1, 0, 0}, 0.3)};
  m = contact_manifold(small, tilted, big, Pose{});
  ASSERT_EQ(m.count, 2);
  EXPECT_NEAR(m.points[0].delta_n, 0.01, 1e-12);
  EXPECT_NEAR(m.points[1].delta_n, 0.01, 1e-12);
  const PartContact g = narrow_phase(small, tilted, big, Pose{});
  EXPECT_NEAR(norm(g.point - (m.points[0].point + m.points[1].point) * 0.5), 0, 1e-12);
}

TEST(ConvexContactManifold, FeatureIdsStableUnderSmallMotion) {
  const ConvexShape big = make_box({2, 2, 0.5}), small = make_box({0.5, 0.5, 0.5});
  const ConvexShape cube = make_box({1, 1, 1});
  auto ids = [](const ContactManifold& m) {
    std::set<std::uint32_t> s;
    for (int k = 0; k < m.count; ++k) s.insert(m.points[k].feature_id);
    return s;
  };
  const auto a0 = ids(contact_manifold(small, Pose{{0.3, 0.2, 0.99}, {}}, big, Pose{}));
  const auto a1 = ids(contact_manifold(small, Pose{{0.31, 0.21, 0.985}, Quat::from_axis_angle({0, 0, 1}, 0.01)}, big, Pose{}));
  EXPECT_EQ(a0.size(), 4u);
  EXPECT_EQ(a0, a1);
  const Quat q = Quat::from_axis_angle({0, 0, 1}, kPi / 4);
  const auto b0 = ids(contact_manifold(cube, Pose{{0, 0, 1.98}, q}, cube, Pose{}));
  const auto b1 = ids(contact_manifold(cube, Pose{{0.001, 0, 1.979}, q}, cube, Pose{}));
  EXPECT_EQ(b0, b1);
}

TEST(ConvexContact, HuetCrossPartsNoNaN) {
  // Two crosses, arm against arm, through every pair of parts as the engine will call it.
  const CompositeShape cross = make_huet_cross(27e-3, 2e-3, 3e-3, 0.3e-3);
  const Pose p1{}, p2{{0.004, 0.003, 0.0029}, Quat::from_axis_angle({1, 1, 0}, 0.3)};
  int touching = 0;
  for (const CompositePart& a : cross.parts)
    for (const CompositePart& b : cross.parts) {
      const PartContact g = narrow_phase(a.shape, p2 * a.pose, b.shape, p1 * b.pose);
      ASSERT_TRUE(std::isfinite(g.delta_n) && std::isfinite(g.point.x));
      touching += g.touching;
      if (g.touching) EXPECT_LT(g.delta_n, 3e-3);
    }
  EXPECT_GT(touching, 0);
}

TEST(ConvexContact, TimingPerQuery) {
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> u(0, 1);
  const int n = 256;
  std::vector<ConvexShape> boxes, sharp, polys;
  std::vector<Pose> pa, pb;
  for (int i = 0; i < n; ++i) {
    boxes.push_back(random_box(rng, false));
    sharp.push_back(make_box(std::get<Box>(boxes.back().geometry).half_extents));
    polys.push_back(random_polyhedron(rng));
    pa.push_back(Pose{{}, random_quat(rng)});
    pb.push_back(Pose{{1.2 + 1.5 * u(rng), 0.3 * u(rng), 0.2 * u(rng)}, random_quat(rng)});
  }
  auto time_ns = [&](auto&& fn) {
    const auto t0 = std::chrono::steady_clock::now();
    double sink = 0;
    const int reps = 40;
    for (int r = 0; r < reps; ++r)
      for (int i = 0; i < n; ++i) sink += fn(i).delta_n;
    const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_TRUE(std::isfinite(sink));
    return ns / (reps * n);
  };
  std::vector<ContactCache> cache(n);
  const double sat = time_ns([&](int i) { return narrow_phase(sharp[i], pa[i], sharp[(i + 1) % n], pb[i]); });
  const double crust = time_ns([&](int i) { return narrow_phase(boxes[i], pa[i], boxes[(i + 1) % n], pb[i]); });
  const double warm =
      time_ns([&](int i) { return narrow_phase(boxes[i], pa[i], boxes[(i + 1) % n], pb[i], &cache[i]); });
  const double poly = time_ns([&](int i) { return narrow_phase(polys[i], pa[i], polys[(i + 1) % n], pb[i]); });
  std::printf("ns/query: box-box SAT %.0f, box-box crust %.0f (warm %.0f), 24-vertex polyhedra crust %.0f\n", sat,
              crust, warm, poly);
}

}  // namespace
}  // namespace talus
