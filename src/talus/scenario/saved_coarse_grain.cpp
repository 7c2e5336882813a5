#include "talus/scenario/saved_coarse_grain.h"

#include <chrono>
#include <charconv>
#include <stdexcept>

#include "talus/analysis/cg_time_average.h"
#include "talus/analysis/coarse_grain.h"
#include "talus/io/csv_writer.h"
#include "talus/io/snapshot_file.h"

namespace talus {

namespace {

constexpr const char* kAxisNames = "xyz";

double parse_number(const std::string& text, const std::string& spec) {
  double v = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, v);
  if (ec != std::errc() || ptr != end || text.empty())
    throw std::invalid_argument("grid \"" + spec + "\": \"" + text + "\" is not a number");
  return v;
}

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

}  // namespace

CgGrid parse_cg_grid(const std::vector<std::string>& axes) {
  if (axes.empty()) throw std::invalid_argument("grid: name at least one axis, e.g. z=0:40:200");
  CgGrid grid;
  for (const std::string& spec : axes) {
    const auto eq = spec.find('=');
    const auto c1 = spec.find(':', eq == std::string::npos ? 0 : eq);
    const auto c2 = c1 == std::string::npos ? std::string::npos : spec.find(':', c1 + 1);
    if (eq != 1 || c1 == std::string::npos || c2 == std::string::npos || spec.find(':', c2 + 1) != std::string::npos)
      throw std::invalid_argument("grid \"" + spec + "\": expected AXIS=LO:HI:N, e.g. z=0:40:200");
    const std::string name = spec.substr(0, 1);
    const auto axis = std::string(kAxisNames).find(name);
    if (axis == std::string::npos) throw std::invalid_argument("grid \"" + spec + "\": the axis is x, y or z");
    if (grid.resolved[axis]) throw std::invalid_argument("grid \"" + spec + "\": axis " + name + " given twice");
    const double lo = parse_number(spec.substr(2, c1 - 2), spec), hi = parse_number(spec.substr(c1 + 1, c2 - c1 - 1), spec);
    const double n = parse_number(spec.substr(c2 + 1), spec);
    if (n < 1 || n != static_cast<int>(n)) throw std::invalid_argument("grid \"" + spec + "\": N must be a whole number >= 1");
    try {
      grid.set_axis(static_cast<int>(axis), lo, hi, static_cast<int>(n));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("grid \"" + spec + "\": " + e.what());
    }
  }
  return grid;
}

SavedCoarseGraining coarse_grain_saved(const std::filesystem::path& results_dir, const CgGrid& grid,
                                       const CgFunction& function, double from, double to) {
  const std::vector<std::filesystem::path> files = io::snapshot_files(results_dir);
  if (files.empty())
    throw std::runtime_error(results_dir.string() + ": no snapshots (run the scenario with run.snapshot_interval > 0)");
  SavedCoarseGraining out;
  CgTimeAverage average;
  for (const auto& file : files) {
    const auto t0 = Clock::now();
    const Snapshot snap = io::read_snapshot_file(file);
    out.read_seconds += seconds_since(t0);
    if (snap.time < from || snap.time > to) continue;
    const auto t1 = Clock::now();
    average.add(coarse_grain(snap, grid, function));
    out.coarse_grain_seconds += seconds_since(t1);
    if (out.snapshots++ == 0) out.first_time = snap.time;
    out.last_time = snap.time;
  }
  if (out.snapshots == 0)
    throw std::runtime_error(results_dir.string() + ": none of the " + std::to_string(files.size()) +
                             " snapshots lies in the time window [" + std::to_string(from) + ", " + std::to_string(to) + "]");
  out.mean = average.mean();
  return out;
}

void write_cg_fields_csv(const std::filesystem::path& path, const CgFields& fields) {
  const CgGrid& g = fields.grid;
  std::vector<std::string> columns;
  for (int a = 0; a < 3; ++a)
    if (g.resolved[a]) columns.push_back(std::string(1, kAxisNames[a]));
  columns.push_back("density");
  for (const char* v : {"momentum", "velocity", "boundary_force"})
    for (int a = 0; a < 3; ++a) columns.push_back(std::string(v) + "_" + kAxisNames[a]);
  for (const char* s : {"stress", "kinetic_stress", "contact_stress", "boundary_stress"})
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) columns.push_back(std::string(s) + "_" + kAxisNames[a] + kAxisNames[b]);
  io::CsvWriter csv(path, columns);
  std::vector<double> row;
  for (int k = 0; k < g.size(); ++k) {
    const CgValues& v = fields.values[k];
    const Vec3 p = g.point(k);
    row.clear();
    for (int a = 0; a < 3; ++a)
      if (g.resolved[a]) row.push_back(a == 0 ? p.x : a == 1 ? p.y : p.z);
    row.push_back(v.density);
    const Vec3 velocity = v.velocity();
    for (const Vec3& x : {v.momentum, velocity, v.boundary_force}) row.insert(row.end(), {x.x, x.y, x.z});
    for (const Eigen::Matrix3d& m : {v.stress(), v.kinetic_stress, v.contact_stress, v.boundary_stress})
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) row.push_back(m(a, b));
    csv.row(std::span<const double>(row));
  }
  csv.close();
}

}  // namespace talus
