#include "talus/analysis/collapse_footprint.h"

#include <stdexcept>
#include <string>

namespace talus::collapse {

Footprint place_footprint(const Footprint& body_frame, const Vec3& position, const Quat& orientation) {
  Footprint world;
  world.boxes.reserve(body_frame.boxes.size());
  for (const FootprintBox& b : body_frame.boxes) {
    world.boxes.push_back({position + orientation.rotate(b.centre), b.half_extents, orientation * b.orientation});
  }
  world.spheres.reserve(body_frame.spheres.size());
  for (const FootprintSphere& s : body_frame.spheres) {
    world.spheres.push_back({position + orientation.rotate(s.centre), s.radius});
  }
  return world;
}

std::vector<Footprint> place_footprints(const Snapshot& snapshot, const std::vector<Footprint>& shapes) {
  std::vector<Footprint> out(snapshot.particles.size());
  for (std::size_t k = 0; k < snapshot.particles.size(); ++k) {
    const ParticleRecord& p = snapshot.particles[k];
    if (p.fixed) continue;
    if (p.shape < 0 || static_cast<std::size_t>(p.shape) >= shapes.size()) {
      throw std::out_of_range("place_footprints: particle " + std::to_string(p.id) + " has shape " +
                              std::to_string(p.shape) + " but only " + std::to_string(shapes.size()) +
                              " footprint templates were given");
    }
    out[k] = place_footprint(shapes[static_cast<std::size_t>(p.shape)], p.position, p.orientation);
  }
  return out;
}

std::vector<Footprint> bounding_sphere_footprints(const Snapshot& snapshot) {
  std::vector<Footprint> out(snapshot.particles.size());
  for (std::size_t k = 0; k < snapshot.particles.size(); ++k) {
    const ParticleRecord& p = snapshot.particles[k];
    if (!p.fixed) out[k].spheres.push_back({p.position, p.radius});
  }
  return out;
}

}  // namespace talus::collapse
