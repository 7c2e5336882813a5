#pragma once
// A pixel picture of the pile seen along one axis, as the camera of the experiments sees it.
// Huet et al. 2021, Sec. III C: runout and heights are measured on such images (pixel 0.43 mm).
#include <cstddef>
#include <vector>

#include "talus/analysis/collapse_footprint.h"

namespace talus::collapse {

// Top: looking down z onto the (x, y) plane. Side: looking along y onto (x, z).
// Front: looking along x onto (y, z). The image axes (u, v) are listed in that order.
enum class View { Top, Side, Front };

struct ImageFrame {
  double u_min = 0, u_max = 0;   ///< m, range of the first image axis (x for Top and Side)
  double v_min = 0, v_max = 0;   ///< m, range of the second image axis (y for Top, z for Side)
  double pixel = 0.43e-3;        ///< m, pixel side; Huet et al. 2021, Sec. III C camera
};

// Each pixel records the highest coordinate, along the view axis, of matter crossing the line
// through the pixel centre (for Top: the height z of the pile surface there). Sampling at the
// pixel centre is exact per pixel, so a block whose edge falls on a pixel boundary is sharp.
struct ProjectionImage {
  View view = View::Top;
  ImageFrame frame;
  int nu = 0, nv = 0;            ///< whole pixels along u and v from u_min, v_min (a partial strip is dropped)
  std::vector<double> top;       ///< m, per pixel, index a * nv + b; -infinity where empty

  std::size_t index(int a, int b) const { return static_cast<std::size_t>(a) * nv + b; }
  bool occupied(int a, int b) const;
  double u_centre(int a) const { return frame.u_min + (a + 0.5) * frame.pixel; }
  double v_centre(int b) const { return frame.v_min + (b + 0.5) * frame.pixel; }
};

// Rasterises every part of every footprint. Cost: one slab test per part and covered pixel.
ProjectionImage rasterise(const std::vector<Footprint>& footprints, View view, const ImageFrame& frame);

// The frame of the whole box for a view: Top is [x] x [y], Side [x] x [z], Front [y] x [z].
ImageFrame frame_of_domain(const Vec3& domain_min, const Vec3& domain_max, View view, double pixel = 0.43e-3);

}  // namespace talus::collapse
