#pragma once
// Which way a column went after the gate opened. Huet et al. 2021, Sec. IV A:
// stable (nothing avalanched), fractured (H_inf = H0: the back of the column stayed in place
// behind a fracture line while the front flowed), collapsed (the whole column avalanched, H_inf < H0).
#include "talus/analysis/snapshot.h"

namespace talus::collapse {

enum class Regime { Stable, Fractured, Collapsed };
const char* to_string(Regime regime);

// All tolerances are in particle sizes d (the caller's length, e.g. circumscribed diameter),
// because the measurements are only as sharp as one particle: a pile edge is ragged by about d.
struct RegimeTolerances {
  double runout = 1.0;              ///< d, how far L_inf may pass L0 for a stable column
  double height = 1.0;              ///< d, how far H_inf may differ from H0 for H to count as kept
  double displacement = 1.0;        ///< d, how far a particle must move to count as displaced
  double displaced_fraction = 0.01; ///< share of displaced particles above which "part has moved"
};

struct RegimeInput {
  double initial_length = 0;   ///< m, L0 (gate position)
  double initial_height = 0;   ///< m, H0 as measured on the initial state
  double runout = 0;           ///< m, L_inf (10 % threshold)
  double final_height = 0;     ///< m, H_inf measured the same way as H0
  double particle_size = 0;    ///< m, d
};

struct RegimeReport {
  Regime regime = Regime::Collapsed;
  double runout_excess = 0;       ///< (L_inf - L0) / d
  double height_change = 0;       ///< |H_inf - H0| / d
  int displaced = 0;              ///< particles (matched by id) that moved more than the tolerance
  double displaced_fraction = 0;  ///< displaced / particles present in both states
};

// Particles present in both snapshots (matched by id, mobile only) that moved more than `distance`.
int count_displaced(const Snapshot& initial, const Snapshot& final, double distance, int* matched = nullptr);

// Decision: H kept (|H_inf - H0| <= height tol) and L kept (L_inf - L0 <= runout tol) and at most
// displaced_fraction of the particles moved by more than a particle: Stable. H kept otherwise:
// Fractured. H lost: Collapsed.
RegimeReport classify_regime(const Snapshot& initial, const Snapshot& final, const RegimeInput& input,
                             const RegimeTolerances& tolerances = {});

}  // namespace talus::collapse
