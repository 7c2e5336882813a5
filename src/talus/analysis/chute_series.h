#pragma once
// Depth-averaged flow quantities of single snapshots (Weinhart et al. 2012, Eqs. 33-35, 42),
// averaged over blocks of time: how steady the flow is inside the averaging window, and the
// blocks from which a mean over the window gets its standard error.
#include <filesystem>
#include <vector>

#include <nlohmann/json.hpp>

#include "talus/analysis/chute_depth_summary.h"

namespace talus {

struct ChuteSeriesRow {
  double time = 0;             ///< sqrt(d/g), the block's last snapshot
  int snapshots = 0;           ///< snapshots averaged in the block
  double height = 0;           ///< h = s - b (Eq. 42)
  double velocity = 0;         ///< u bar (Eq. 33)
  double volume_fraction = 0;  ///< rho bar / rho_p
  double froude = 0;           ///< F (Eq. 36)
};

class ChuteSeries {
 public:
  explicit ChuteSeries(double block_length = 1) : block_length_(block_length) {}

  // One snapshot's summary at `time`; a block ends at the first snapshot block_length after the
  // block's first one.
  void add(double time, const ChuteDepthSummary& s);
  // Closes the open block, if any (the end of a run).
  void finish();

  const std::vector<ChuteSeriesRow>& rows() const { return rows_; }
  void write_csv(const std::filesystem::path& path) const;

  nlohmann::json state() const;
  void restore(const nlohmann::json& j);

 private:
  double block_length_;
  double block_start_ = 0;
  ChuteSeriesRow sum_;  ///< the open block's sums
  std::vector<ChuteSeriesRow> rows_;
};

}  // namespace talus
