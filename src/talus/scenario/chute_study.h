#pragma once
// The chute study of Weinhart et al. 2012 inside a run: the flow state from the energies
// (Sect. 6) and time-averaged coarse-grained depth profiles (Sect. 7, Eq. 43), read from
// [chute.flow_state] and [chute.coarse_graining].
#include <memory>
#include <vector>

#include "talus/analysis/cg_function.h"
#include "talus/analysis/chute_flow_state.h"
#include "talus/io/scenario_file.h"
#include "talus/scenario/run_observer.h"

namespace talus {

struct ChuteStudyConfig {
  FlowStateCriteria criteria;
  bool stop_when_arrested = false;  ///< end the run once E_kin/E_ela < arrest_ratio (h_stop search)
  bool coarse_grain = false;        ///< [chute.coarse_graining] present
  double start = 0;                 ///< sqrt(d/g), first snapshot of the averaging window
  double end = 0;                   ///< sqrt(d/g), last snapshot (run end by default)
  double interval = 0;              ///< sqrt(d/g) between snapshots: t_c / 2 (Eq. 43)
  double series_interval = 1;       ///< sqrt(d/g), length of a block of chute_series.csv
  CgKernel kernel = CgKernel::gaussian;
  double width = 0.25;              ///< d, Gaussian w (Sect. 7 chooses 0.25), or the Lucy cutoff c
  std::vector<double> extra_widths; ///< further widths, profiles written alongside (Fig. 6)
  double z_min = 0, z_max = 0;      ///< d, profile range
  int points = 0;                   ///< profile points
  double diameter = 1;              ///< d of the flowing particles
  double particle_density = 0;      ///< rho_p
  double time_step = 0;             ///< sqrt(d/g), the run's: snapshot times are known to half of it
};

// Reads [chute.flow_state] and [chute.coarse_graining] (every key optional). `contact_time` is
// t_c, `end_time` the run's end, `fill_height` H and `base_diameter` lambda set the defaults.
ChuteStudyConfig read_chute_study(const io::ScenarioFile& f, double contact_time, double end_time, double fill_height,
                                  double base_diameter, double particle_density);

std::unique_ptr<RunObserver> make_chute_observer(const ChuteStudyConfig& config);

}  // namespace talus
