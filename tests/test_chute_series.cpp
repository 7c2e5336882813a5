// Block averages of the chute's depth-averaged quantities (chute_series.csv).
#include <gtest/gtest.h>

#include "talus/analysis/chute_series.h"

namespace talus {
namespace {

ChuteDepthSummary summary_with(double velocity, double volume_fraction) {
  ChuteDepthSummary s;
  s.averages.velocity = velocity;
  s.averages.surface.base = 0;
  s.averages.surface.surface = 10 * volume_fraction;
  s.volume_fraction = volume_fraction;
  s.froude = 2 * velocity;
  return s;
}

TEST(ChuteSeries, BlocksCloseOnTheSnapshotThatCompletesThem) {
  ChuteSeries series(1.0);
  // Snapshots every 0.25: a block holds five (its first and the one a block length later).
  for (int k = 0; k <= 10; ++k) series.add(0.25 * k, summary_with(k, 0.5 + 0.01 * k));
  series.finish();
  const auto& rows = series.rows();
  ASSERT_EQ(rows.size(), 3u);  // [0, 1], [1.25, 2.25], [2.5]
  EXPECT_EQ(rows[0].snapshots, 5);
  EXPECT_DOUBLE_EQ(rows[0].time, 1.0);
  EXPECT_DOUBLE_EQ(rows[0].velocity, 2.0);  // mean of 0..4
  EXPECT_DOUBLE_EQ(rows[0].volume_fraction, 0.52);
  EXPECT_DOUBLE_EQ(rows[0].height, 5.2);
  EXPECT_DOUBLE_EQ(rows[0].froude, 4.0);
  EXPECT_EQ(rows[1].snapshots, 5);
  EXPECT_DOUBLE_EQ(rows[1].velocity, 7.0);  // mean of 5..9
  EXPECT_EQ(rows[2].snapshots, 1);
  EXPECT_DOUBLE_EQ(rows[2].velocity, 10.0);
}

TEST(ChuteSeries, StateRestoresAnOpenBlock) {
  ChuteSeries whole(1.0), first(1.0);
  for (int k = 0; k <= 6; ++k) first.add(0.25 * k, summary_with(k, 0.5));
  ChuteSeries resumed(1.0);
  resumed.restore(first.state());  // as a checkpoint in the middle of the second block
  for (int k = 7; k <= 10; ++k) resumed.add(0.25 * k, summary_with(k, 0.5));
  for (int k = 0; k <= 10; ++k) whole.add(0.25 * k, summary_with(k, 0.5));
  resumed.finish();
  whole.finish();
  ASSERT_EQ(resumed.rows().size(), whole.rows().size());
  for (std::size_t r = 0; r < whole.rows().size(); ++r) {
    EXPECT_EQ(resumed.rows()[r].snapshots, whole.rows()[r].snapshots);
    EXPECT_DOUBLE_EQ(resumed.rows()[r].velocity, whole.rows()[r].velocity);
  }
}

}  // namespace
}  // namespace talus
