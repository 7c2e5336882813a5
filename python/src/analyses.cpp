// The analyses of a Snapshot as its methods: coarse-grained fields (analysis/coarse_grain.h),
// the contact force PDF (force_network_pdf.h) and the fabric (fabric.h). They run alike on a
// live Simulation (Simulation.snapshot()) and on a snapshot file (talus.read_snapshot).
#include <optional>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "numpy_values.h"
#include "talus/analysis/coarse_grain.h"
#include "talus/analysis/fabric.h"
#include "talus/analysis/force_network.h"
#include "talus/analysis/force_network_pdf.h"

namespace talus::python {

namespace {

constexpr const char* kAxes[3] = {"x", "y", "z"};

// {"z": (lo, hi, n), ...}: n points from lo to hi on each axis named; the others are averaged.
CgGrid grid_of(const py::dict& axes) {
  CgGrid grid;
  for (const auto& [key, value] : axes) {
    const std::string name = py::cast<std::string>(key);
    int axis = 0;
    while (axis < 3 && name != kAxes[axis]) ++axis;
    if (axis == 3) throw py::value_error("grid: axis \"" + name + "\" is not x, y or z");
    const auto [lo, hi, n] = py::cast<std::tuple<double, double, int>>(value);
    grid.set_axis(axis, lo, hi, n);  // std::invalid_argument (ValueError) for a bad range
  }
  if (grid.dim() == 0) throw py::value_error("grid: resolve at least one axis, e.g. {\"z\": (0, 0.1, 101)}");
  return grid;
}

// Fields on the grid as arrays shaped by the resolved axes (in x, y, z order) and then by the
// field's own components: density (...), velocity (..., 3), stress (..., 3, 3).
class GridArrays {
 public:
  explicit GridArrays(const CgFields& fields) : fields_(fields) {
    for (int a = 0; a < 3; ++a)
      if (fields.grid.resolved[a]) shape_.push_back(fields.grid.n[a]);
  }
  template <class Get>
  py::array_t<double> scalar(Get get) const {
    return fill(shape_, [&](const CgValues& v, double* out) { *out = get(v); });
  }
  template <class Get>
  py::array_t<double> vector(Get get) const {
    return fill(with(3), [&](const CgValues& v, double* out) {
      const Vec3 x = get(v);
      out[0] = x.x, out[1] = x.y, out[2] = x.z;
    });
  }
  template <class Get>
  py::array_t<double> matrix(Get get) const {
    return fill(with(3, 3), [&](const CgValues& v, double* out) {
      const Eigen::Matrix3d m = get(v);
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) out[3 * r + c] = m(r, c);
    });
  }

 private:
  template <class... Extra>
  std::vector<py::ssize_t> with(Extra... extra) const {
    std::vector<py::ssize_t> s = shape_;
    (s.push_back(extra), ...);
    return s;
  }
  // CgGrid numbers its points x fastest; the arrays are C-ordered, z fastest.
  template <class Put>
  py::array_t<double> fill(const std::vector<py::ssize_t>& shape, Put put) const {
    py::array_t<double> a(shape);
    const CgGrid& g = fields_.grid;
    const std::size_t per_point = static_cast<std::size_t>(a.size()) / g.size();
    double* data = a.mutable_data();
    for (int k = 0; k < g.size(); ++k) {
      const int ix = k % g.n[0], iy = (k / g.n[0]) % g.n[1], iz = k / (g.n[0] * g.n[1]);
      const std::size_t at = (static_cast<std::size_t>(ix) * g.n[1] + iy) * g.n[2] + iz;
      put(fields_.values[k], data + at * per_point);
    }
    return a;
  }
  const CgFields& fields_;
  std::vector<py::ssize_t> shape_;
};

py::dict coarse_grain_fields(const Snapshot& s, const py::dict& axes, double width, const std::string& function,
                             std::optional<double> cutoff) {
  const CgGrid grid = grid_of(axes);
  if (!(width > 0)) throw py::value_error("width must be positive");
  CgFunction f;
  if (function == "gaussian")
    f = CgFunction::gaussian(width, grid.dim(), cutoff.value_or(0));
  else if (function == "lucy" && !cutoff)
    f = CgFunction::lucy(width, grid.dim());
  else
    throw py::value_error(function == "lucy" ? "lucy: width is the cutoff; give no cutoff"
                                             : "function must be \"gaussian\" or \"lucy\"");
  const CgFields fields = coarse_grain(s, grid, f);
  const GridArrays arrays(fields);
  py::dict d;
  for (int a = 0; a < 3; ++a) {
    if (!grid.resolved[a]) continue;
    py::array_t<double> x(grid.n[a]);
    for (int i = 0; i < grid.n[a]; ++i) x.mutable_at(i) = grid.coordinate(a, i);
    d[kAxes[a]] = x;
  }
  d["density"] = arrays.scalar([](const CgValues& v) { return v.density; });
  d["momentum"] = arrays.vector([](const CgValues& v) { return v.momentum; });
  d["velocity"] = arrays.vector([](const CgValues& v) { return v.velocity(); });
  d["stress"] = arrays.matrix([](const CgValues& v) { return v.stress(); });
  d["kinetic_stress"] = arrays.matrix([](const CgValues& v) { return v.kinetic_stress; });
  d["contact_stress"] = arrays.matrix([](const CgValues& v) { return v.contact_stress; });
  d["boundary_stress"] = arrays.matrix([](const CgValues& v) { return v.boundary_stress; });
  d["momentum_flux"] = arrays.matrix([](const CgValues& v) { return v.momentum_flux; });
  d["boundary_force"] = arrays.vector([](const CgValues& v) { return v.boundary_force; });
  return d;
}

PairPoints pair_points(bool merge_pairs) { return merge_pairs ? PairPoints::MergePerPair : PairPoints::EachPoint; }

py::dict force_pdf(const Snapshot& s, int bins, const std::string& scale, double min_ratio, double max_ratio,
                   bool merge_pairs, bool include_walls) {
  if (bins < 1) throw py::value_error("bins must be at least 1");
  const std::vector<double> forces = contact_force_magnitudes(s, pair_points(merge_pairs), include_walls);
  ForcePdf pdf;
  if (scale == "linear" && min_ratio == 0)
    pdf = force_pdf_linear(forces, bins, max_ratio);
  else if (scale == "log")
    pdf = force_pdf_log(forces, bins, min_ratio, max_ratio);
  else
    throw py::value_error(scale == "linear" ? "linear bins start at 0: give no min_ratio"
                                            : "scale must be \"linear\" or \"log\"");
  py::dict d;
  d["edges"] = to_numpy(pdf.edges);
  d["centres"] = to_numpy(pdf.centres);
  d["density"] = to_numpy(pdf.density);
  d["mean_force"] = pdf.mean_force;
  d["samples"] = pdf.samples;
  d["outside"] = pdf.outside;
  return d;
}

py::array_t<double> fabric(const Snapshot& s, bool merge_pairs) {
  const FabricTensor t = fabric_tensor(s, pair_points(merge_pairs));
  py::array_t<double> a({3, 3});
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) a.mutable_at(r, c) = t[r][c];
  return a;
}

py::dict fabric_in_xz(const Snapshot& s, bool merge_pairs) {
  const PlaneFabric f = fabric_xz(s, pair_points(merge_pairs));
  py::dict d;
  d["xx"] = f.xx;
  d["xz"] = f.xz;
  d["zz"] = f.zz;
  d["anisotropy"] = f.anisotropy;
  d["direction"] = f.direction;
  return d;
}

py::dict fabric_histogram(const Snapshot& s, int bins, bool merge_pairs) {
  if (bins < 1) throw py::value_error("bins must be at least 1");
  const FabricHistogram h = fabric_angle_histogram(s, bins, pair_points(merge_pairs));
  py::dict d;
  d["edges"] = to_numpy(h.edges);
  d["centres"] = to_numpy(h.centres);
  d["density"] = to_numpy(h.density);
  d["samples"] = h.samples;
  return d;
}

}  // namespace

void bind_analyses(py::class_<Snapshot>& c) {
  c.def("coarse_grain", &coarse_grain_fields, py::arg("grid"), py::arg("width"), py::arg("function") = "gaussian",
        py::arg("cutoff") = py::none(),
        "Fields of Weinhart et al. 2012, Sect. 3 on grid {axis: (lo, hi, n)}: density, momentum, velocity, "
        "stresses (Pa, compression positive), boundary_force; Gaussian of std width cut at cutoff (3 width), "
        "or Lucy of cutoff width.")
      .def("force_pdf", &force_pdf, py::arg("bins") = 50, py::arg("scale") = "linear", py::arg("min_ratio") = 0.0,
           py::arg("max_ratio") = 0.0, py::arg("merge_pairs") = false, py::arg("include_walls") = false,
           "PDF of F / <F> over the contact points, on linear or log bins (Huet et al. 2021, Fig. 15).")
      .def("fabric_tensor", &fabric, py::arg("merge_pairs") = false,
           "<n n> of the unit branch vectors of particle contacts (3 x 3, trace 1).")
      .def("fabric_xz", &fabric_in_xz, py::arg("merge_pairs") = false,
           "The fabric in the xz plane: xx, xz, zz, anisotropy, direction (Huet et al. 2021, Figs. 16-17).")
      .def("fabric_histogram", &fabric_histogram, py::arg("bins") = 36, py::arg("merge_pairs") = false,
           "Density of the branch vectors' angle to x in the xz plane over [0, pi).");
}

}  // namespace talus::python
