#pragma once
// Flow states of a chute run from its energies over time (Weinhart et al. 2012, Sects. 6 and 8,
// Figs. 3 and 10): arrested, steady, accelerating; over smoother bases also layered and
// oscillating. Reads the ratio of kinetic to mean elastic energy, E_kin / <E_ela>.
#include <optional>
#include <string>
#include <vector>

namespace talus {

enum class FlowState {
  arrested,      ///< E_kin / E_ela fell below the arrest threshold (Sect. 6)
  steady,        ///< the energy ratio is time independent over the final window (Fig. 3)
  accelerating,  ///< the energy ratio keeps rising over the final window (Fig. 3, dashed)
  decelerating,  ///< the ratio keeps falling but has not reached the arrest threshold yet
  layered,       ///< steady, with the bulk ordered into layers (Fig. 10, bottom left)
  oscillating,   ///< the ratio swings between ordered and disordered levels (Fig. 10, bottom right)
  undetermined,  ///< too few samples in the final window to say
};

std::string to_string(FlowState s);
// The inverse of to_string; throws std::invalid_argument for any other text.
FlowState flow_state_from_string(const std::string& text);

struct EnergySample {
  double time = 0;     ///< sqrt(d/g)
  double kinetic = 0;  ///< m g d, translational plus rotational
  double elastic = 0;  ///< m g d, normal plus tangential springs
};

struct FlowStateCriteria {
  // Sect. 6: "Flow was defined to be arrested when the energy ratio E_kin/<E_ela> fell below
  // 1e-5 within 500 time units".
  double arrest_ratio = 1e-5;
  double arrest_time = 500;
  // Sect. 6 judges steadiness on [1800, 2000], the last tenth of the run: the final window is
  // this fraction of the run (at least min_window time units).
  double window_fraction = 0.1;
  double min_window = 10;
  // Steady: the least-squares line through the ratio changes by less than this fraction of its
  // mean across the window. Chosen so that the turbulence-like fluctuations of steady flow
  // (about 10 % rms at H = 20) pass and the steady rise of accelerating flow (Fig. 3: a factor
  // 2 over 200 time units at theta = 30 deg) does not.
  double drift_tolerance = 0.2;
  // Oscillating: the ratio's rms about its trend line exceeds this fraction of its mean (the
  // stop-and-go flow of Fig. 10 swings by factors of several).
  double oscillation_tolerance = 0.5;
  // Layered: the bulk density's rms about its mean, relative to the mean, above this (coarse
  // graining width 0.25 d). Disordered flow smooths to a few per cent in the bulk (Fig. 6); the
  // layered flow of Fig. 10 swings by tens of per cent through the whole depth.
  double layering_tolerance = 0.15;
};

struct FlowStateResult {
  FlowState state = FlowState::undetermined;
  std::optional<double> arrest_time;  ///< first time E_kin/E_ela < arrest_ratio, if any
  double window_start = 0, window_end = 0;
  double mean_ratio = 0;      ///< mean of E_kin / <E_ela> over the window
  double relative_drift = 0;  ///< change of the fitted line across the window / mean
  double relative_rms = 0;    ///< rms about the fitted line / mean
};

// The first time at which E_kin / E_ela < criteria.arrest_ratio (a sample with no elastic energy
// but motion never counts as arrested).
std::optional<double> arrest_time(const std::vector<EnergySample>& samples, const FlowStateCriteria& c);

// The state from the energies alone (arrested, steady, accelerating, decelerating, oscillating,
// or undetermined). <E_ela> is the mean elastic energy over the final window.
FlowStateResult classify_flow(const std::vector<EnergySample>& samples, const FlowStateCriteria& c = {});

// Refines a steady state to layered when the bulk density profile is layered: `layering` is
// the relative rms of the density in the bulk (see layering_index in chute_depth_summary.h).
FlowState refine_with_layering(FlowState s, double layering, const FlowStateCriteria& c = {});

}  // namespace talus
