#include "talus/shape/mass_properties.h"

#include "talus/shape/part_intersection.h"
#include "talus/shape/volume_moments.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace talus {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

using Moments = VolumeMoments;

MassProperties finish(const Moments& m, double density) {
  MassProperties mp;
  mp.volume = m.volume;
  mp.mass = density * m.volume;
  const Vector3d com = m.first / m.volume;
  mp.centre_of_mass = {com.x(), com.y(), com.z()};
  const Matrix3d c = density * (m.second - m.volume * com * com.transpose());  // central second moment
  mp.inertia = c.trace() * Matrix3d::Identity() - c;
  const Eigen::SelfAdjointEigenSolver<Matrix3d> eig(0.5 * (mp.inertia + mp.inertia.transpose()));
  mp.principal_moments = {eig.eigenvalues()(0), eig.eigenvalues()(1), eig.eigenvalues()(2)};
  // Moments that differ by round-off only are equal: a body with a symmetry axis (a cross, a
  // cylinder) then turns as the exact symmetric top, with no residual flow made of round-off
  // (rigid_rotation.h), and a body of cubic symmetry as an isotropic one.
  Vec3& moments = mp.principal_moments;
  const double round_off = 1e-12 * moments[2];
  for (int k = 0; k < 2; ++k)
    if (moments[k + 1] - moments[k] <= round_off) moments[k] = moments[k + 1] = 0.5 * (moments[k] + moments[k + 1]);
  if (moments[2] - moments[0] <= round_off) moments[0] = moments[1] = moments[2];
  Matrix3d axes = eig.eigenvectors();
  if (axes.determinant() < 0) axes.col(2) = -axes.col(2);  // proper rotation
  const Eigen::Quaterniond q(axes);
  mp.principal_orientation = Quat{q.w(), q.x(), q.y(), q.z()}.normalized();
  return mp;
}

// Rotation maps every axis onto an axis: the part is an axis-aligned box in the body frame.
bool axis_aligned(const Quat& q) {
  for (int k = 0; k < 3; ++k) {
    Vec3 e;
    e[k] = 1;
    const Vec3 r = q.rotate(e);
    int big = 0;
    for (int j = 0; j < 3; ++j) {
      if (std::abs(std::abs(r[j]) - 1) < 1e-12) ++big;
      else if (std::abs(r[j]) > 1e-12) return false;
    }
    if (big != 1) return false;
  }
  return true;
}

// Union of axis-aligned boxes, exactly: the box faces cut space into cells each wholly in or out.
Moments aligned_box_union(const std::vector<Aabb>& boxes) {
  std::vector<double> cuts[3];
  for (const Aabb& b : boxes)
    for (int k = 0; k < 3; ++k) {
      cuts[k].push_back(b.lo[k]);
      cuts[k].push_back(b.hi[k]);
    }
  for (auto& c : cuts) {
    std::sort(c.begin(), c.end());
    c.erase(std::unique(c.begin(), c.end()), c.end());
  }
  Moments m;
  for (std::size_t i = 0; i + 1 < cuts[0].size(); ++i)
    for (std::size_t j = 0; j + 1 < cuts[1].size(); ++j)
      for (std::size_t k = 0; k + 1 < cuts[2].size(); ++k) {
        const Vec3 lo{cuts[0][i], cuts[1][j], cuts[2][k]}, hi{cuts[0][i + 1], cuts[1][j + 1], cuts[2][k + 1]};
        const Vec3 mid = (lo + hi) * 0.5;
        const bool inside = std::any_of(boxes.begin(), boxes.end(), [&](const Aabb& b) {
          return mid.x > b.lo.x && mid.x < b.hi.x && mid.y > b.lo.y && mid.y < b.hi.y && mid.z > b.lo.z &&
                 mid.z < b.hi.z;
        });
        if (inside) m += box_moments((hi - lo) * 0.5, mid);
      }
  return m;
}

// Moments of the multiply covered volume, weighted by (cover count - 1), by the midpoint rule.
Moments overlap_excess(const CompositeShape& c, int cells_longest) {
  const int n = static_cast<int>(c.parts.size());
  std::vector<Aabb> boxes(n);
  for (int i = 0; i < n; ++i) boxes[i] = aabb(c.parts[i].shape.geometry, c.parts[i].pose);
  bool any = false;
  Aabb region{{1e300, 1e300, 1e300}, {-1e300, -1e300, -1e300}};
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      Aabb o;
      bool ok = true;
      for (int k = 0; k < 3; ++k) {
        o.lo[k] = std::max(boxes[i].lo[k], boxes[j].lo[k]);
        o.hi[k] = std::min(boxes[i].hi[k], boxes[j].hi[k]);
        ok = ok && o.lo[k] < o.hi[k];
      }
      if (!ok) continue;
      any = true;
      for (int k = 0; k < 3; ++k) {
        region.lo[k] = std::min(region.lo[k], o.lo[k]);
        region.hi[k] = std::max(region.hi[k], o.hi[k]);
      }
    }
  Moments m;
  if (!any) return m;
  const Vec3 size = region.hi - region.lo;
  const double h = std::max({size.x, size.y, size.z}) / cells_longest;
  int cells[3];
  Vec3 step;
  for (int k = 0; k < 3; ++k) {
    cells[k] = std::max(1, static_cast<int>(std::ceil(size[k] / h)));
    step[k] = size[k] / cells[k];
  }
  auto count_at = [&](const Vec3& p) {
    int count = 0;
    for (int q = 0; q < n; ++q) {
      const Aabb& b = boxes[q];
      if (p.x < b.lo.x || p.x > b.hi.x || p.y < b.lo.y || p.y > b.hi.y || p.z < b.lo.z || p.z > b.hi.z) continue;
      if (contains(c.parts[q].shape.geometry, c.parts[q].pose.to_child(p))) ++count;
    }
    return count;
  };
  // Cover counts on the grid nodes; a cell whose 8 corners agree is taken as uniform, a mixed
  // (boundary) cell is split into kSub^3 midpoint sub-cells: boundary resolution h / kSub.
  constexpr int kSub = 8;
  const int nx = cells[0] + 1, ny = cells[1] + 1, nz = cells[2] + 1;
  std::vector<unsigned char> node(static_cast<std::size_t>(nx) * ny * nz);
  auto at = [&](int i, int j, int k) -> unsigned char& { return node[(static_cast<std::size_t>(i) * ny + j) * nz + k]; };
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k)
        at(i, j, k) = static_cast<unsigned char>(count_at(region.lo + Vec3{i * step.x, j * step.y, k * step.z}));
  const Moments cell = box_moments(step * 0.5, Vec3{});
  const Vec3 sub_step = step / kSub;
  const Moments sub = box_moments(sub_step * 0.5, Vec3{});
  for (int i = 0; i < cells[0]; ++i)
    for (int j = 0; j < cells[1]; ++j)
      for (int k = 0; k < cells[2]; ++k) {
        const int c0 = at(i, j, k);
        bool uniform = true;
        for (int q = 1; q < 8 && uniform; ++q) uniform = at(i + (q & 1), j + (q >> 1 & 1), k + (q >> 2 & 1)) == c0;
        const Vec3 lo = region.lo + Vec3{i * step.x, j * step.y, k * step.z};
        if (uniform) {
          if (c0 > 1) m += transformed(cell, Pose{lo + step * 0.5, Quat{}}) * (c0 - 1);
          continue;
        }
        for (int a = 0; a < kSub; ++a)
          for (int b = 0; b < kSub; ++b)
            for (int d = 0; d < kSub; ++d) {
              const Vec3 p = lo + Vec3{(a + 0.5) * sub_step.x, (b + 0.5) * sub_step.y, (d + 0.5) * sub_step.z};
              if (const int cnt = count_at(p); cnt > 1) m += transformed(sub, Pose{p, Quat{}}) * (cnt - 1);
            }
      }
  return m;
}

// Inclusion-exclusion over the parts that meet: V(union) = sum V(P_i) - sum V(P_i & P_j) + ...
// Subsets grow only from ones of non-zero volume, so parts that meet in pairs cost pairs.
// nullopt when some common volume has no closed form (part_intersection.h).
std::optional<Moments> union_by_inclusion_exclusion(const CompositeShape& c) {
  const int n = static_cast<int>(c.parts.size());
  Moments total;
  std::vector<int> subset;
  bool exact = true;
  auto grow = [&](auto&& self, int next) -> void {
    for (int i = next; i < n && exact; ++i) {
      subset.push_back(i);
      const std::optional<Moments> common = intersection_moments(c, subset);
      if (!common) exact = false;
      else if (common->volume > 0) {
        total += *common * (subset.size() % 2 == 1 ? 1.0 : -1.0);
        self(self, i + 1);
      }
      subset.pop_back();
    }
  };
  grow(grow, 0);
  if (!exact) return std::nullopt;
  return total;
}

}  // namespace

MassProperties mass_properties(const ConvexGeometry& g, double density) { return finish(moments(g), density); }

MassProperties mass_properties(const ConvexShape& s, double density) { return mass_properties(s.geometry, density); }

MassProperties mass_properties(const CompositeShape& c, double density, const CompositeMassOptions& options) {
  bool all_aligned_boxes = !options.force_quadrature;
  std::vector<Aabb> boxes;
  for (const CompositePart& p : c.parts) {
    const Box* b = std::get_if<Box>(&p.shape.geometry);
    if (!b || !axis_aligned(p.pose.orientation)) {
      all_aligned_boxes = false;
      break;
    }
    Aabb a;
    const Vec3 e = p.pose.orientation.rotate(b->half_extents);
    for (int k = 0; k < 3; ++k) {
      a.lo[k] = p.pose.position[k] - std::abs(e[k]);
      a.hi[k] = p.pose.position[k] + std::abs(e[k]);
    }
    boxes.push_back(a);
  }
  if (all_aligned_boxes) return finish(aligned_box_union(boxes), density);
  if (!options.force_quadrature)
    if (const std::optional<Moments> exact = union_by_inclusion_exclusion(c)) return finish(*exact, density);

  Moments m;
  for (const CompositePart& p : c.parts) m += transformed(moments(p.shape.geometry), p.pose);
  const Moments excess = overlap_excess(c, options.quadrature_cells);
  m += excess * -1.0;
  return finish(m, density);
}

CompositeShape to_principal_frame(const CompositeShape& c, const MassProperties& mp) {
  const Pose frame = mp.principal_pose();
  const Pose inverse{frame.orientation.rotate_inverse(-frame.position), frame.orientation.conjugate()};
  CompositeShape out;
  for (const CompositePart& p : c.parts) out.add(p.shape, inverse * p.pose);
  return out;
}

}  // namespace talus
