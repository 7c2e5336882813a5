#pragma once
// Reads one set of contact parameters from a scenario file, with each key looked up in a chain
// of tables (e.g. a pair's own table, then the [contact] defaults). A contact is composed of
// sub-models, each chosen by a key (docs/contact_models.md):
//   normal      "linear" | "hertz"                       (contact/normal_laws.h)
//   damping     "viscous" | "tsuji"                      (how the dashpot follows the stiffness)
//   tangential  "memory" | "elastic_spring" | "mindlin" | "memoryless" | "none"
//   rolling     "huet" | "none"
// and `model` ("memory", "memoryless", "elastic_spring") is the shorthand of earlier files.
#include <string>
#include <vector>

#include "talus/contact/contact_law.h"
#include "talus/io/scenario_file.h"

namespace talus {

struct ContactContext {
  double reduced_mass = 0;    ///< kg, nominal m_ij of the contact (walls: the particle's mass)
  double radius_i = 0;        ///< m, nominal radii and moments of inertia for Eqs. (18)-(19)
  double inertia_i = 0;
  double radius_j = 0;        ///< 0 for a wall
  double inertia_j = 0;
  TangentialModel model = TangentialModel::memory;  ///< the run's tangential history rule
  bool wall = false;          ///< a particle against a (rigid) wall
  bool shaped = false;        ///< a non-spherical body takes part
  double reduced_radius() const { return wall ? radius_i : radius_i * radius_j / (radius_i + radius_j); }
};

// The run's tangential history rule, from contact.tangential or the contact.model shorthand.
// Every contact of a run shares it (the force loops are compiled per rule); "mindlin" keeps
// the elastic spring's rule, "none" fits any.
TangentialModel read_tangential_model(const io::ScenarioFile& file);

// `tables` in priority order; each key is read from the first table that has it.
ContactParams read_contact(const io::ScenarioFile& file, const std::vector<std::string>& tables,
                           const ContactContext& context);

// The duration of a head-on impact of this contact (s): t_c of Weinhart et al. 2012, Eq. (5) for
// a linear spring, the damped Hertz impact at params.impact_speed otherwise.
double contact_duration(const ContactParams& params, double reduced_mass, double reduced_radius);

}  // namespace talus
