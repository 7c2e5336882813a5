#include "talus/shape/part_intersection.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "talus/collide/gjk.h"

namespace talus {
namespace {

struct Plane {
  Vec3 normal;  ///< outward unit normal
  double offset = 0;  ///< dot(normal, x) <= offset inside (m)
};

bool polyhedral(const ConvexGeometry& g) {
  return std::holds_alternative<Box>(g) || std::holds_alternative<ConvexPolyhedron>(g);
}

// Face planes of a polyhedral part in the body frame.
void add_planes(const CompositePart& part, std::vector<Plane>& out) {
  std::vector<Plane> local;
  if (const auto* b = std::get_if<Box>(&part.shape.geometry)) {
    for (int k = 0; k < 3; ++k) {
      Vec3 n;
      n[k] = 1;
      local.push_back({n, b->half_extents[k]});
      local.push_back({-1.0 * n, b->half_extents[k]});
    }
  } else {
    for (const HullFace& f : std::get<ConvexPolyhedron>(part.shape.geometry).hull.faces) local.push_back({f.normal, f.offset});
  }
  for (const Plane& p : local) {
    const Vec3 n = part.pose.orientation.rotate(p.normal);
    out.push_back({n, p.offset + dot(n, part.pose.position)});
  }
}

// The intersection of half-spaces as a hull: its vertices are where three planes meet inside
// all the others. Planes of n parts number a few tens, so the cubic enumeration costs little.
VolumeMoments halfspace_intersection(const std::vector<Plane>& planes, double scale) {
  const double tolerance = 1e-10 * scale;
  const std::size_t m = planes.size();
  std::vector<Vec3> corners;
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = i + 1; j < m; ++j) {
      const Vec3 nij = cross(planes[i].normal, planes[j].normal);
      if (norm2(nij) < 1e-20) continue;
      for (std::size_t k = j + 1; k < m; ++k) {
        const double det = dot(planes[k].normal, nij);
        if (std::abs(det) < 1e-10) continue;
        const Vec3 x = (cross(planes[j].normal, planes[k].normal) * planes[i].offset +
                        cross(planes[k].normal, planes[i].normal) * planes[j].offset + nij * planes[k].offset) /
                       det;
        const bool inside = std::all_of(planes.begin(), planes.end(),
                                        [&](const Plane& p) { return dot(p.normal, x) <= p.offset + tolerance; });
        if (inside) corners.push_back(x);
      }
    }
  if (corners.size() < 4) return {};
  try {
    return polyhedron_moments(build_convex_hull(corners));
  } catch (const std::invalid_argument&) {
    return {};  // the parts only touch: a face, an edge or a point
  }
}

// Two balls: a lens, the cap of each beyond the plane of their intersection circle.
VolumeMoments lens(const Vec3& ca, double ra, const Vec3& cb, double rb) {
  const double d = norm(cb - ca);
  if (d >= ra + rb) return {};
  if (d <= std::abs(ra - rb)) return ra < rb ? spherical_cap_moments(ra, 2 * ra, ca, {0, 0, 1})
                                             : spherical_cap_moments(rb, 2 * rb, cb, {0, 0, 1});
  const Vec3 axis = (cb - ca) / d;
  const double plane = (d * d + ra * ra - rb * rb) / (2 * d);  // from ca along axis
  VolumeMoments m = spherical_cap_moments(ra, ra - plane, ca, axis);
  m += spherical_cap_moments(rb, rb - (d - plane), cb, -1.0 * axis);
  return m;
}

// A ball centred on a cylinder's axis at distance s beyond one of its caps (s >= 0), whose
// surface passes through that cap's rim or inside it (R^2 <= s^2 + r^2): every section of the
// ball inside the cylinder lies within the cylinder's disc, so their common part is the ball's
// cap of height R - s on the cylinder's side (a half ball for a ball of the cylinder's radius
// on the cap's centre, as in a rod), when the cylinder is at least that long.
std::optional<VolumeMoments> capped_cylinder(const Sphere& s, const Pose& ps, const Cylinder& c, const Pose& pc) {
  const double tolerance = 1e-12 * c.radius;
  const Vec3 axis = pc.orientation.rotate({0, 0, 1});
  for (const double side : {1.0, -1.0}) {
    const Vec3 outward = axis * side;
    const Vec3 cap = pc.position + outward * c.half_height;
    const Vec3 offset = ps.position - cap;
    const double beyond = dot(offset, outward);
    if (beyond < -tolerance || norm(offset - outward * beyond) > tolerance) continue;  // not on the axis past this cap
    const double height = s.radius - std::max(beyond, 0.0);
    if (height <= 0) return VolumeMoments{};
    if (s.radius * s.radius > beyond * beyond + c.radius * c.radius + 2 * tolerance * c.radius || height > 2 * c.half_height)
      return std::nullopt;
    return spherical_cap_moments(s.radius, height, ps.position, -1.0 * outward);
  }
  return std::nullopt;
}

// Two convex parts a positive distance apart (GJK on their sharp geometry) meet in nothing.
bool parts_apart(const CompositePart& a, const CompositePart& b) {
  const PosedSupport sa{&a.shape.geometry, a.pose}, sb{&b.shape.geometry, b.pose};
  GjkOptions options;
  options.warm_direction = b.pose.position - a.pose.position;
  options.scale = bounding_radius(a.shape.geometry) + bounding_radius(b.shape.geometry);
  options.max_iterations = 128;
  const GjkResult r = gjk_distance(sa, sb, options);
  return !r.intersecting && r.distance > 1e-9 * options.scale;
}

bool boxes_apart(const CompositeShape& c, const std::vector<int>& subset) {
  Aabb common{{-1e300, -1e300, -1e300}, {1e300, 1e300, 1e300}};
  for (int i : subset) {
    const Aabb b = aabb(c.parts[i].shape.geometry, c.parts[i].pose);
    for (int k = 0; k < 3; ++k) {
      common.lo[k] = std::max(common.lo[k], b.lo[k]);
      common.hi[k] = std::min(common.hi[k], b.hi[k]);
      if (common.lo[k] >= common.hi[k]) return true;
    }
  }
  return false;
}

}  // namespace

std::optional<VolumeMoments> intersection_moments(const CompositeShape& c, const std::vector<int>& subset) {
  if (subset.size() == 1) return transformed(moments(c.parts[subset[0]].shape.geometry), c.parts[subset[0]].pose);
  if (boxes_apart(c, subset)) return VolumeMoments{};
  const bool all_polyhedral = std::all_of(subset.begin(), subset.end(),
                                          [&](int i) { return polyhedral(c.parts[i].shape.geometry); });
  if (all_polyhedral) {
    std::vector<Plane> planes;
    double scale = 0;
    for (int i : subset) {
      add_planes(c.parts[i], planes);
      scale = std::max(scale, norm(c.parts[i].pose.position) + bounding_radius(c.parts[i].shape.geometry));
    }
    return halfspace_intersection(planes, scale);
  }
  for (std::size_t i = 0; i < subset.size(); ++i)  // any two apart: nothing in common
    for (std::size_t j = i + 1; j < subset.size(); ++j)
      if (parts_apart(c.parts[subset[i]], c.parts[subset[j]])) return VolumeMoments{};
  if (subset.size() != 2) return std::nullopt;
  const CompositePart& a = c.parts[subset[0]];
  const CompositePart& b = c.parts[subset[1]];
  const auto* sa = std::get_if<Sphere>(&a.shape.geometry);
  const auto* sb = std::get_if<Sphere>(&b.shape.geometry);
  if (sa && sb) return lens(a.pose.position, sa->radius, b.pose.position, sb->radius);
  const auto* ca = std::get_if<Cylinder>(&a.shape.geometry);
  const auto* cb = std::get_if<Cylinder>(&b.shape.geometry);
  if (sa && cb) return capped_cylinder(*sa, a.pose, *cb, b.pose);
  if (sb && ca) return capped_cylinder(*sb, b.pose, *ca, a.pose);
  return std::nullopt;
}

}  // namespace talus
