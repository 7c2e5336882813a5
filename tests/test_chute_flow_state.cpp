// Flow states from energy series of known shape (Weinhart et al. 2012, Sect. 6, Figs. 3 and 10):
// the arrest criterion E_kin/E_ela < 1e-5 within 500 time units, steady, accelerating and
// oscillating ratios, and layering read from the bulk density.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "talus/analysis/chute_flow_state.h"

namespace talus {
namespace {

// Samples every time unit to t_end, E_ela = 100, E_kin = 100 * ratio(t) with 10 % noise.
template <class Ratio>
std::vector<EnergySample> series(double t_end, Ratio ratio, double noise = 0.1) {
  std::mt19937 rng(7);
  std::normal_distribution<double> n(0, noise);
  std::vector<EnergySample> s;
  for (double t = 0; t <= t_end + 1e-9; t += 1) s.push_back({t, 100 * ratio(t) * (1 + n(rng)), 100});
  return s;
}

TEST(ChuteFlowState, ArrestWithinFiveHundredTimeUnits) {
  // Fig. 3: theta <= 20.5 deg, the kinetic energy vanishes after a short time.
  const auto s = series(600, [](double t) { return std::exp(-t / 10); }, 0);
  const FlowStateResult r = classify_flow(s);
  EXPECT_EQ(r.state, FlowState::arrested);
  ASSERT_TRUE(r.arrest_time);
  EXPECT_EQ(*r.arrest_time, std::ceil(10 * std::log(1e5)));  // first sample with exp(-t/10) < 1e-5
  // The same decay ten times slower crosses 1e-5 at t = 1151 > 500: flowing by Sect. 6's test.
  const auto slow = series(1000, [](double t) { return std::exp(-t / 100); }, 0);
  EXPECT_FALSE(arrest_time(slow, {}));
  EXPECT_NE(classify_flow(slow).state, FlowState::arrested);
}

TEST(ChuteFlowState, ConstantRatioIsSteadyRisingRatioAccelerates) {
  EXPECT_EQ(classify_flow(series(2000, [](double) { return 0.5; })).state, FlowState::steady);
  // Fig. 3, theta >= 30 deg: the ratio keeps growing (here doubling over the final 200 units).
  const FlowStateResult acc = classify_flow(series(2000, [](double t) { return 0.5 * std::pow(2.0, t / 200); }));
  EXPECT_EQ(acc.state, FlowState::accelerating);
  EXPECT_NEAR(acc.relative_drift, std::log(2.0), 0.15);  // d ln(ratio) over the window
  EXPECT_EQ(classify_flow(series(2000, [](double t) { return 0.5 * std::pow(2.0, -t / 200); })).state,
            FlowState::decelerating);
}

TEST(ChuteFlowState, StopAndGoIsOscillating) {
  // Fig. 10, bottom right: the ratio swings between an ordered (low) and disordered (high) level.
  const auto s = series(2000, [](double t) { return std::fmod(t, 40) < 20 ? 0.05 : 1.0; });
  const FlowStateResult r = classify_flow(s);
  EXPECT_EQ(r.state, FlowState::oscillating);
  EXPECT_GT(r.relative_rms, 0.8);
}

TEST(ChuteFlowState, LayeringRefinesOnlySteadyFlow) {
  EXPECT_EQ(refine_with_layering(FlowState::steady, 0.3), FlowState::layered);
  EXPECT_EQ(refine_with_layering(FlowState::steady, 0.03), FlowState::steady);
  EXPECT_EQ(refine_with_layering(FlowState::accelerating, 0.3), FlowState::accelerating);
  EXPECT_EQ(to_string(FlowState::layered), "layered");
}

TEST(ChuteFlowState, TooFewSamplesIsUndetermined) {
  EXPECT_EQ(classify_flow({}).state, FlowState::undetermined);
  EXPECT_EQ(classify_flow({{0, 1, 1}, {1, 1, 1}}).state, FlowState::undetermined);
}

}  // namespace
}  // namespace talus
