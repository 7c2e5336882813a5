// What a checkpoint carries of a pour: std::mt19937_64 streams its whole state as text.
#include <sstream>
#include <stdexcept>

#include "talus/scenario/pouring.h"

namespace talus {

nlohmann::json Pouring::state() const {
  std::ostringstream rng;
  rng << rng_;
  return {{"rng", rng.str()}, {"poured", poured_}, {"next_time", next_time_}};
}

void Pouring::restore(const nlohmann::json& state) {
  std::istringstream rng(state.at("rng").get<std::string>());
  rng >> rng_;
  if (!rng) throw std::invalid_argument("pour random generator state unreadable");
  poured_ = state.at("poured").get<std::size_t>();
  next_time_ = state.at("next_time").get<double>();
}

}  // namespace talus
