#include "talus/analysis/collapse_image.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace talus::collapse {
namespace {

constexpr double kEmpty = -std::numeric_limits<double>::infinity();

struct Axes {
  int u, v, view;  // world axis of the image axes and of the line of sight
};

Axes axes_of(View view) {
  switch (view) {
    case View::Top: return {0, 1, 2};
    case View::Side: return {0, 2, 1};
    case View::Front: return {1, 2, 0};
  }
  return {0, 1, 2};
}

Vec3 unit(int axis) {
  Vec3 e;
  e[axis] = 1;
  return e;
}

// Pixel index range [first, last] whose centres may lie in [lo, hi].
void pixel_range(double lo, double hi, double origin, double pixel, int count, int& first, int& last) {
  first = std::max(0, static_cast<int>(std::floor((lo - origin) / pixel - 0.5)));
  last = std::min(count - 1, static_cast<int>(std::ceil((hi - origin) / pixel - 0.5)));
}

// Highest parameter t at which the line point + t * dir is inside the box, or kEmpty:
// the slab test in the box frame.
double box_line_top(const FootprintBox& box, const Vec3& point, const Vec3& dir_body) {
  const Vec3 o = box.orientation.rotate_inverse(point - box.centre);
  double t_lo = -std::numeric_limits<double>::infinity();
  double t_hi = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    const double h = box.half_extents[k];
    if (std::abs(dir_body[k]) < 1e-12) {
      if (std::abs(o[k]) > h) return kEmpty;
      continue;
    }
    double t1 = (-h - o[k]) / dir_body[k];
    double t2 = (h - o[k]) / dir_body[k];
    if (t1 > t2) std::swap(t1, t2);
    t_lo = std::max(t_lo, t1);
    t_hi = std::min(t_hi, t2);
    if (t_lo > t_hi) return kEmpty;
  }
  return t_hi;
}

void stamp(ProjectionImage& image, int a, int b, double value) {
  double& cell = image.top[image.index(a, b)];
  cell = std::max(cell, value);
}

void rasterise_box(ProjectionImage& image, const Axes& ax, const FootprintBox& box) {
  const ImageFrame& f = image.frame;
  // Half extent of the projected box along the image axes: sum over box axes of |R e_k| h_k.
  double ext_u = 0, ext_v = 0;
  for (int k = 0; k < 3; ++k) {
    const Vec3 axis_world = box.orientation.rotate(unit(k));
    ext_u += std::abs(axis_world[ax.u]) * box.half_extents[k];
    ext_v += std::abs(axis_world[ax.v]) * box.half_extents[k];
  }
  int a0, a1, b0, b1;
  pixel_range(box.centre[ax.u] - ext_u, box.centre[ax.u] + ext_u, f.u_min, f.pixel, image.nu, a0, a1);
  pixel_range(box.centre[ax.v] - ext_v, box.centre[ax.v] + ext_v, f.v_min, f.pixel, image.nv, b0, b1);
  const Vec3 dir_body = box.orientation.rotate_inverse(unit(ax.view));
  for (int a = a0; a <= a1; ++a) {
    for (int b = b0; b <= b1; ++b) {
      Vec3 point;  // on the line of sight, at view coordinate 0, so t is the view coordinate
      point[ax.u] = image.u_centre(a);
      point[ax.v] = image.v_centre(b);
      const double t = box_line_top(box, point, dir_body);
      if (t != kEmpty) stamp(image, a, b, t);
    }
  }
}

void rasterise_sphere(ProjectionImage& image, const Axes& ax, const FootprintSphere& s) {
  const ImageFrame& f = image.frame;
  const double cu = s.centre[ax.u], cv = s.centre[ax.v], r = s.radius;
  int a0, a1, b0, b1;
  pixel_range(cu - r, cu + r, f.u_min, f.pixel, image.nu, a0, a1);
  pixel_range(cv - r, cv + r, f.v_min, f.pixel, image.nv, b0, b1);
  for (int a = a0; a <= a1; ++a) {
    for (int b = b0; b <= b1; ++b) {
      const double du = image.u_centre(a) - cu, dv = image.v_centre(b) - cv;
      const double rho2 = du * du + dv * dv;
      if (rho2 <= r * r) stamp(image, a, b, s.centre[ax.view] + std::sqrt(r * r - rho2));
    }
  }
}

int pixel_count(double lo, double hi, double pixel) {
  // Whole pixels only, so every pixel centre lies in the frame (a partial last strip would be
  // half outside the channel and read as empty); the slack keeps an exact fit from losing one.
  return std::max(0, static_cast<int>(std::floor((hi - lo) / pixel + 1e-9)));
}

}  // namespace

bool ProjectionImage::occupied(int a, int b) const { return top[index(a, b)] != kEmpty; }

ProjectionImage rasterise(const std::vector<Footprint>& footprints, View view, const ImageFrame& frame) {
  ProjectionImage image;
  image.view = view;
  image.frame = frame;
  image.nu = pixel_count(frame.u_min, frame.u_max, frame.pixel);
  image.nv = pixel_count(frame.v_min, frame.v_max, frame.pixel);
  image.top.assign(static_cast<std::size_t>(image.nu) * image.nv, kEmpty);
  const Axes ax = axes_of(view);
  for (const Footprint& fp : footprints) {
    for (const FootprintBox& box : fp.boxes) rasterise_box(image, ax, box);
    for (const FootprintSphere& s : fp.spheres) rasterise_sphere(image, ax, s);
  }
  return image;
}

ImageFrame frame_of_domain(const Vec3& domain_min, const Vec3& domain_max, View view, double pixel) {
  const Axes ax = axes_of(view);
  return {domain_min[ax.u], domain_max[ax.u], domain_min[ax.v], domain_max[ax.v], pixel};
}

}  // namespace talus::collapse
