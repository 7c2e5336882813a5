#pragma once
// The columns and rows of a run's timeseries.csv: time, step, energies, contact counts, speeds,
// the force on every wall and, with domain.on_leave = "delete", the particles removed so far.
// A checkpoint carries the column names, so that a restart refuses another scenario's.
#include <string>
#include <vector>

#include "talus/scenario/blowup_guard.h"
#include "talus/world/world.h"

namespace talus {

std::vector<std::string> timeseries_columns(const World& world, LeavePolicy on_leave);

// One row, up to the wall forces; the run loop appends the count of removed particles.
std::vector<double> timeseries_row(const World& world, const Diagnostics& d);

}  // namespace talus
