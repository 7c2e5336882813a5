#include "talus/world/placed_bodies.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

#include "talus/world/parallel.h"

namespace talus {

// Writes every field in place: the parts of all bodies are placed each step, and building a
// temporary then copying it (a 128-byte part) cost a memset and a memmove per part. The pose
// is never assembled as a Pose either: the compiler spilled it to the stack and read it back
// with wider loads than it had stored, and each such read waited for the store queue to drain.
void place_part(const CompositePart& part, const Pose& body, PlacedPart& p) {
  p.box.centre = body.to_parent(part.pose.position);
  rotation_axes(body.orientation * part.pose.orientation, p.box.axis);
  const Box* b = std::get_if<Box>(&part.shape.geometry);
  p.box.half = b ? b->half_extents : Vec3{};
  p.is_box = b != nullptr;
}

void PlacedBodies::place(const ParticleStore& p, const std::vector<CompositeShape>& shapes) {
  const std::size_t n = p.position.size();
  const bool restart = restart_travel_ || travel_.size() != n;
  if (restart) {
    // Particles are added, removed or reordered only at a rebuild: the layout holds till the next.
    offset_.resize(n + 1);
    std::uint32_t parts = 0;
    for (std::size_t i = 0; i < n; ++i) {
      offset_[i] = parts;
      if (p.shape[i] != 0) parts += static_cast<std::uint32_t>(shapes[p.shape[i]].parts.size());
    }
    offset_[n] = parts;
    bodies_.resize(n);
    parts_.resize(parts);
    last_position_.assign(p.position.begin(), p.position.end());
    last_orientation_.assign(p.orientation.begin(), p.orientation.end());
    travel_.assign(n, 0.0);
    travel_clock_ = 0;
    restart_travel_ = false;
  }
  const long count = static_cast<long>(n);
  double largest_step = 0;
#pragma omp parallel for schedule(static) reduction(max : largest_step) if (worth_parallel(4 * n))
  for (long i = 0; i < count; ++i) {
    if (!restart) {
      // |vec(q_new q_old^*)| = sin(theta / 2) for the turn theta between the two poses.
      const Quat turn = p.orientation[i] * last_orientation_[i].conjugate();
      const double half_sine = std::sqrt(turn.x * turn.x + turn.y * turn.y + turn.z * turn.z);
      const double step = norm(p.position[i] - last_position_[i]) + 2 * p.radius[i] * half_sine;
      travel_[i] += step;
      // A body whose motion is not a number wakes every pair it is in: so must the clock.
      largest_step = std::max(largest_step, std::isnan(step) ? std::numeric_limits<double>::infinity() : step);
      last_position_[i] = p.position[i];
      last_orientation_[i] = p.orientation[i];
    }
    if (p.shape[i] == 0) continue;
    const CompositeShape& s = shapes[p.shape[i]];
    BodyFrame& b = bodies_[i];
    rotation_axes(p.orientation[i], b.axis);
    b.box_centre = p.position[i] + b.axis[0] * s.box_centre.x + b.axis[1] * s.box_centre.y + b.axis[2] * s.box_centre.z;
    const Pose body{p.position[i], p.orientation[i]};
    PlacedPart* out = parts_.data() + offset_[i];
    for (std::size_t a = 0; a < s.parts.size(); ++a) place_part(s.parts[a], body, out[a]);
  }
  travel_clock_ += largest_step;
}

}  // namespace talus
