#pragma once
// Mean particle speeds of a snapshot and their free-fall scaling.
// Huet et al. 2021, Sec. IV B 2, Figs. 12-13: v_avg / sqrt(g H_i) against t / tau_c,
// tau_c = sqrt(H_i / g), with H_i the initial column height.
#include "talus/analysis/snapshot.h"

namespace talus::collapse {

struct MeanSpeeds {
  double translational = 0;  ///< m/s, mean of |v| over mobile particles
  double angular = 0;        ///< rad/s, mean of |omega| over mobile particles
};

MeanSpeeds mean_speeds(const Snapshot& snapshot);

// tau_c = sqrt(H0 / g), s.
double collapse_time_scale(double initial_height, double g);

// One point of the curves of Figs. 12-13.
struct ScaledSpeeds {
  double time = 0;           ///< (t - t_gate) / tau_c
  double translational = 0;  ///< v_avg / sqrt(g H0)
  double angular = 0;        ///< omega_avg tau_c (the paper plots only the translational curve)
};

// g is |snapshot.gravity|; t_gate is the time the gate opened, s.
ScaledSpeeds scaled_speeds(const Snapshot& snapshot, double initial_height, double t_gate = 0);

}  // namespace talus::collapse
