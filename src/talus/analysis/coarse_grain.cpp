#include "talus/analysis/coarse_grain.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <omp.h>

namespace talus {
namespace {

Eigen::Vector3d eig(const Vec3& v) { return {v.x, v.y, v.z}; }

// The box seen by the coarse graining: which axes are resolved, periodic, and the averaging
// volume factor 1 / (product of box lengths along the averaged axes).
struct Frame {
  bool resolved[3] = {};
  bool periodic[3] = {};
  double length[3] = {};  // m
  double inv_area = 1;    // 1/m^(3-dim)

  Frame(const Snapshot& snap, const CgGrid& grid) {
    for (int a = 0; a < 3; ++a) {
      resolved[a] = grid.resolved[a];
      periodic[a] = snap.periodic[a];
      length[a] = snap.domain_max[a] - snap.domain_min[a];
      if (!resolved[a]) {
        if (!(length[a] > 0)) throw std::invalid_argument("coarse_grain: averaged axis needs a box length");
        inv_area /= length[a];
      }
    }
  }
  Vec3 project(const Vec3& v) const {
    return {resolved[0] ? v.x : 0, resolved[1] ? v.y : 0, resolved[2] ? v.z : 0};
  }
  Vec3 min_image(Vec3 d) const {
    for (int a = 0; a < 3; ++a)
      if (periodic[a]) d[a] -= length[a] * std::round(d[a] / length[a]);
    return d;
  }
};

// One contact's stress source: tensor f (x) branch spread along start -> start - branch.
struct Segment {
  Vec3 start;              // m, centre of the flowing particle i
  Vec3 branch;             // m, r_ij (flowing pair) or r_i - c (boundary contact)
  Eigen::Matrix3d tensor;  // N m, f (x) branch
  bool boundary = false;   // with a fixed particle or a wall
  Vec3 contact;            // m, contact point (boundary contacts)
  Vec3 force;              // N, force on the flowing particle (boundary contacts)
};

std::vector<Segment> make_segments(const Snapshot& snap, const Frame& fr) {
  std::vector<Segment> segs;
  segs.reserve(snap.contacts.size());
  const auto& ps = snap.particles;
  for (const ContactRecord& c : snap.contacts) {
    const bool flow_i = !ps[c.i].fixed;
    const bool flow_j = c.j >= 0 && !ps[c.j].fixed;
    Segment s;
    if (flow_i && flow_j) {
      s.start = ps[c.i].position;
      s.branch = fr.min_image(ps[c.i].position - ps[c.j].position);  // r_ij = r_i - r_j
      s.force = c.force;
    } else if (flow_i || flow_j) {
      // Eqs. 27-28 with the line ending at the contact point: f (x) (r_i - c).
      const int k = flow_i ? c.i : c.j;
      s.start = ps[k].position;
      s.branch = fr.min_image(ps[k].position - c.point);
      s.force = flow_i ? c.force : -c.force;  // Newton's third law for the force on j
      s.boundary = true;
      s.contact = ps[k].position - s.branch;  // the image of c next to particle k
    } else {
      continue;  // fixed-fixed: not part of the flow
    }
    s.tensor = eig(s.force) * eig(s.branch).transpose();
    segs.push_back(s);
  }
  return segs;
}

// Grid-point ranges along one axis that a source spanning [lo, hi] reaches, per periodic image.
// Every image within reach counts, so a cutoff wider than half the box is still a correct
// periodic sum.
constexpr int kMaxImages = 8;
struct AxisSpan {
  int count = 0;
  int begin[kMaxImages], end[kMaxImages];  // index ranges [begin, end)
  double shift[kMaxImages];                // m, image offset added to the source
};

AxisSpan axis_span(const CgGrid& g, const Frame& fr, int a, double lo, double hi) {
  AxisSpan s;
  if (!g.resolved[a]) {
    s.count = 1;
    s.begin[0] = 0, s.end[0] = 1, s.shift[0] = 0;
    return s;
  }
  const double h = g.spacing(a), length = fr.length[a];
  int m_lo = 0, m_hi = 0;
  if (fr.periodic[a]) {
    m_lo = int(std::ceil((g.lo[a] - hi) / length));
    m_hi = int(std::floor((g.hi[a] - lo) / length));
  }
  for (int m = m_lo; m <= m_hi; ++m) {
    const double shift = m * length;
    int b, e;
    if (h > 0) {
      b = std::max(0, int(std::ceil((lo + shift - g.lo[a]) / h)));
      e = std::min(g.n[a], int(std::floor((hi + shift - g.lo[a]) / h)) + 1);
    } else {
      b = 0;
      e = (g.lo[a] >= lo + shift && g.lo[a] <= hi + shift) ? 1 : 0;
    }
    if (e <= b) continue;
    if (s.count == kMaxImages) throw std::invalid_argument("coarse_grain: cutoff spans too many periodic images");
    s.begin[s.count] = b, s.end[s.count] = e, s.shift[s.count] = shift;
    ++s.count;
  }
  return s;
}

// Calls fn(k, shift) for each grid point k within the box [lo, hi] (a source's reach) or one
// of its periodic images, shift being the image offset.
template <class Fn>
void visit(const CgGrid& g, const Frame& fr, const Vec3& lo, const Vec3& hi, Fn&& fn) {
  const AxisSpan sx = axis_span(g, fr, 0, lo.x, hi.x);
  const AxisSpan sy = axis_span(g, fr, 1, lo.y, hi.y);
  const AxisSpan sz = axis_span(g, fr, 2, lo.z, hi.z);
  for (int cz = 0; cz < sz.count; ++cz)
    for (int iz = sz.begin[cz]; iz < sz.end[cz]; ++iz)
      for (int cy = 0; cy < sy.count; ++cy)
        for (int iy = sy.begin[cy]; iy < sy.end[cy]; ++iy)
          for (int cx = 0; cx < sx.count; ++cx)
            for (int ix = sx.begin[cx]; ix < sx.end[cx]; ++ix)
              fn(g.index(ix, iy, iz), Vec3{sx.shift[cx], sy.shift[cy], sz.shift[cz]});
}

void add_particle(CgValues& v, const ParticleRecord& p, double w) {
  const double mw = p.mass * w;
  v.density += mw;
  v.momentum += p.velocity * mw;
  const Eigen::Vector3d u = eig(p.velocity);
  v.momentum_flux.noalias() += mw * u * u.transpose();
}

void add_segment(CgValues& v, const Segment& s, double line) {
  if (s.boundary) v.boundary_stress += line * s.tensor;
  else v.contact_stress += line * s.tensor;
}

// Scales by the averaging area and forms the kinetic stress.
void finish(CgValues& v, double inv_area) {
  v.density *= inv_area;
  v.momentum *= inv_area;
  v.momentum_flux *= inv_area;
  v.contact_stress *= inv_area;
  v.boundary_stress *= inv_area;
  v.boundary_force *= inv_area;
  v.form_kinetic_stress();
}

void add_into(CgValues& to, const CgValues& from) {
  to.density += from.density;
  to.momentum += from.momentum;
  to.momentum_flux += from.momentum_flux;
  to.contact_stress += from.contact_stress;
  to.boundary_stress += from.boundary_stress;
  to.boundary_force += from.boundary_force;
}

void check(const Snapshot& snap, const CgGrid& grid, const CgFunction& f) {
  if (f.dim != grid.dim()) throw std::invalid_argument("coarse_grain: function and grid dimensions differ");
  for (const ContactRecord& c : snap.contacts)
    if (c.i < 0 || c.i >= int(snap.particles.size()) || c.j >= int(snap.particles.size()))
      throw std::invalid_argument("coarse_grain: contact refers to a missing particle");
}

}  // namespace

CgFields coarse_grain(const Snapshot& snap, const CgGrid& grid, const CgFunction& f, std::size_t mass_sources) {
  check(snap, grid, f);
  const Frame fr(snap, grid);
  const std::vector<Segment> segs = make_segments(snap, fr);
  const double c = f.cutoff;
  std::vector<Vec3> coords(grid.size());
  for (int k = 0; k < grid.size(); ++k) coords[k] = fr.project(grid.point(k));
  const Vec3 reach = fr.project({c, c, c});
  const auto& ps = snap.particles;
  const int nps = int(std::min(ps.size(), mass_sources)), nsegs = int(segs.size());

  std::vector<std::vector<CgValues>> partial(omp_get_max_threads());
#pragma omp parallel
  {
    std::vector<CgValues>& acc = partial[omp_get_thread_num()];
    acc.assign(grid.size(), CgValues{});
    // Static schedules: each thread always gets the same sources, so sums are reproducible.
#pragma omp for schedule(static) nowait
    for (int i = 0; i < nps; ++i) {
      if (ps[i].fixed) continue;
      const Vec3 x = fr.project(ps[i].position);
      visit(grid, fr, x - reach, x + reach, [&](int k, const Vec3& shift) {
        const double w = f.value(norm2(coords[k] - x - shift));
        if (w > 0) add_particle(acc[k], ps[i], w);
      });
    }
#pragma omp for schedule(static)
    for (int n = 0; n < nsegs; ++n) {
      const Segment& s = segs[n];
      const Vec3 a0 = fr.project(s.start), b = fr.project(s.branch), a1 = a0 - b;
      const Vec3 lo{std::min(a0.x, a1.x), std::min(a0.y, a1.y), std::min(a0.z, a1.z)};
      const Vec3 hi{std::max(a0.x, a1.x), std::max(a0.y, a1.y), std::max(a0.z, a1.z)};
      // Eq. 26: W(r - r_i + s r_ij) integrated over s in [0, 1].
      visit(grid, fr, lo - reach, hi + reach, [&](int k, const Vec3& shift) {
        const double line = cg_line_integral(f, coords[k] - a0 - shift, b);
        if (line > 0) add_segment(acc[k], s, line);
      });
      if (s.boundary) {
        const Vec3 xc = fr.project(s.contact);
        visit(grid, fr, xc - reach, xc + reach, [&](int k, const Vec3& shift) {
          const double w = f.value(norm2(coords[k] - xc - shift));
          if (w > 0) acc[k].boundary_force += s.force * w;
        });
      }
    }
  }
  CgFields out;
  out.grid = grid;
  out.values = std::move(partial[0]);
  for (std::size_t t = 1; t < partial.size(); ++t)  // a team smaller than the maximum leaves some empty
    for (std::size_t k = 0; k < partial[t].size(); ++k) add_into(out.values[k], partial[t][k]);
  for (CgValues& v : out.values) finish(v, fr.inv_area);
  return out;
}

CgValues coarse_grain_at(const Snapshot& snap, const CgGrid& grid, const CgFunction& f,
                         const Vec3& point) {
  check(snap, grid, f);
  const Frame fr(snap, grid);
  const std::vector<Segment> segs = make_segments(snap, fr);
  for (int a = 0; a < 3; ++a) {
    if (!(grid.resolved[a] && fr.periodic[a])) continue;
    double reach = 0;
    for (const Segment& s : segs) reach = std::max(reach, std::abs(s.branch[a]));
    if (2 * f.cutoff + reach >= fr.length[a])
      throw std::invalid_argument("coarse_grain_at: cutoff too wide for the minimum image");
  }
  CgValues v;
  for (const ParticleRecord& p : snap.particles) {
    if (p.fixed) continue;
    const double w = f.value(norm2(fr.project(fr.min_image(point - p.position))));
    if (w > 0) add_particle(v, p, w);
  }
  for (const Segment& s : segs) {
    // The image of the segment whose midpoint is nearest to the point.
    const Vec3 to_mid = fr.project(fr.min_image(point - (s.start - 0.5 * s.branch)));
    const Vec3 b = fr.project(s.branch);
    const double line = cg_line_integral(f, to_mid - 0.5 * b, b);
    if (line > 0) add_segment(v, s, line);
    if (s.boundary) v.boundary_force += s.force * f.value(norm2(fr.project(fr.min_image(point - s.contact))));
  }
  finish(v, fr.inv_area);
  return v;
}

}  // namespace talus
