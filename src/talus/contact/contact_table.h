#pragma once
// Contact parameters for every pair of species and every species-wall material pair, so that
// particle-particle, particle-wall and flow-base contacts are set independently.
#include <stdexcept>
#include <vector>

#include "talus/contact/contact_params.h"

namespace talus {

class ContactTable {
 public:
  void resize(int species, int wall_materials) {
    species_ = species;
    materials_ = wall_materials;
    pair_.assign(static_cast<std::size_t>(species) * species, {});
    wall_.assign(static_cast<std::size_t>(species) * wall_materials, {});
  }
  int species() const { return species_; }
  int wall_materials() const { return materials_; }

  const ContactParams& pair(int a, int b) const { return pair_[a * species_ + b]; }
  const ContactParams& wall(int s, int material) const { return wall_[s * materials_ + material]; }
  void set_pair(int a, int b, const ContactParams& p) {
    pair_[a * species_ + b] = p;
    pair_[b * species_ + a] = p;
  }
  void set_wall(int s, int material, const ContactParams& p) { wall_[s * materials_ + material] = p; }

  bool any_rolling() const {
    for (const auto& p : pair_) if (p.rolling.enabled) return true;
    for (const auto& p : wall_) if (p.rolling.enabled) return true;
    return false;
  }

 private:
  int species_ = 0, materials_ = 0;
  std::vector<ContactParams> pair_, wall_;
};

}  // namespace talus
