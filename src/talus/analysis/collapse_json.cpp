#include "talus/analysis/collapse_json.h"

namespace talus::collapse {

namespace {

nlohmann::json vector_json(const Vec3& v) { return {v.x, v.y, v.z}; }

nlohmann::json height_json(const HeightProfile& h) {
  return {{"mean", h.mean}, {"q1", h.q1}, {"median", h.median}, {"q3", h.q3}, {"y", h.y}, {"h", h.h}};
}

}  // namespace

nlohmann::json collapse_measures_json(const CollapseMeasures& m) {
  return {
      {"H0", m.initial_height.mean},
      {"final_height", m.final_height.mean},
      {"runout", m.runout.nominal},
      {"runout_low", m.runout.low},
      {"runout_high", m.runout.high},
      {"runout_reached_box_end", m.runout.reached_frame_end},
      {"aspect_ratio", m.aspect_ratio},
      {"runout_ratio", m.runout_ratio},
      {"runout_ratio_low", m.runout_ratio_low},
      {"runout_ratio_high", m.runout_ratio_high},
      {"height_ratio", m.height_ratio},
      {"height_ratio_low", m.height_ratio_low},
      {"height_ratio_high", m.height_ratio_high},
      {"com_initial", vector_json(m.centre_of_mass.initial)},
      {"com_final", vector_json(m.centre_of_mass.final)},
      {"com_displacement", vector_json(m.centre_of_mass.displacement)},
      {"com_ratio", m.centre_ratio},
      {"regime", to_string(m.regime.regime)},
      {"displaced_particles", m.regime.displaced},
      {"displaced_fraction", m.regime.displaced_fraction},
      {"initial_height_profile", height_json(m.initial_height)},
      {"final_height_profile", height_json(m.final_height)},
      {"runout_profile", {{"x", m.runout.profile.x}, {"intensity", m.runout.profile.intensity}}},
  };
}

}  // namespace talus::collapse
