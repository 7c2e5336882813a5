#include "talus/analysis/chute_series.h"

#include "talus/io/csv_writer.h"

namespace talus {

void ChuteSeries::add(double time, const ChuteDepthSummary& s) {
  if (sum_.snapshots == 0) block_start_ = time;
  sum_.time = time;
  ++sum_.snapshots;
  sum_.height += s.averages.surface.height();
  sum_.velocity += s.averages.velocity;
  sum_.volume_fraction += s.volume_fraction;
  sum_.froude += s.froude;
  // The block closes on the snapshot that completes it, so blocks hold equal counts when
  // snapshots are evenly spaced (a tiny margin: their times carry round-off).
  if (time - block_start_ >= block_length_ * (1 - 1e-9) - 1e-12) finish();
}

void ChuteSeries::finish() {
  if (sum_.snapshots == 0) return;
  const double n = sum_.snapshots;
  rows_.push_back({sum_.time, sum_.snapshots, sum_.height / n, sum_.velocity / n, sum_.volume_fraction / n,
                   sum_.froude / n});
  sum_ = {};
}

void ChuteSeries::write_csv(const std::filesystem::path& path) const {
  io::CsvWriter csv(path, {"time", "snapshots", "h", "mean_velocity", "volume_fraction", "froude"});
  for (const ChuteSeriesRow& r : rows_)
    csv.row({r.time, r.snapshots, r.height, r.velocity, r.volume_fraction, r.froude});
  csv.close();
}

namespace {
nlohmann::json row_json(const ChuteSeriesRow& r) {
  return {r.time, r.snapshots, r.height, r.velocity, r.volume_fraction, r.froude};
}
ChuteSeriesRow row_from(const nlohmann::json& j) {
  return {j.at(0).get<double>(), j.at(1).get<int>(),    j.at(2).get<double>(),
          j.at(3).get<double>(), j.at(4).get<double>(), j.at(5).get<double>()};
}
}  // namespace

nlohmann::json ChuteSeries::state() const {
  nlohmann::json rows = nlohmann::json::array();
  for (const ChuteSeriesRow& r : rows_) rows.push_back(row_json(r));
  return {{"block_start", block_start_}, {"open", row_json(sum_)}, {"rows", rows}};
}

void ChuteSeries::restore(const nlohmann::json& j) {
  block_start_ = j.at("block_start").get<double>();
  sum_ = row_from(j.at("open"));
  rows_.clear();
  for (const auto& r : j.at("rows")) rows_.push_back(row_from(r));
}

}  // namespace talus
