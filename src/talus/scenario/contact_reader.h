#pragma once
// Reads one set of contact parameters from a scenario file, with each key looked up in a chain
// of tables (e.g. a pair's own table, then the [contact] defaults).
#include <string>
#include <vector>

#include "talus/contact/contact_params.h"
#include "talus/io/scenario_file.h"

namespace talus {

struct ContactContext {
  double reduced_mass = 0;    ///< kg, nominal m_ij of the contact (walls: the particle's mass)
  double radius_i = 0;        ///< m, nominal radii and moments of inertia for Eqs. (18)-(19)
  double inertia_i = 0;
  double radius_j = 0;        ///< 0 for a wall
  double inertia_j = 0;
};

// `tables` in priority order; each key is read from the first table that has it.
ContactParams read_contact(const io::ScenarioFile& file, const std::vector<std::string>& tables,
                           const ContactContext& context);

}  // namespace talus
