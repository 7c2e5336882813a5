#include "talus/scenario/dam_break.h"

#include <limits>
#include <stdexcept>

#include "talus/scenario/body_insertion.h"
#include "talus/scenario/contact_reader.h"

namespace talus {

DamBreakSetup read_dam_break(const io::ScenarioFile& f) {
  DamBreakSetup s;
  s.box_length = f.get_or<double>("dam_break.box_length", s.box_length, io::positive);
  s.box_height = f.get_or<double>("dam_break.box_height", s.box_height, io::positive);
  s.width = f.get_or<double>("dam_break.width", s.width, io::positive);
  s.gate_position = f.get_or<double>("dam_break.gate_position", s.gate_position, io::positive);
  if (s.gate_position >= s.box_length) f.fail("dam_break.gate_position", "must be inside the box (below box_length)");
  s.domain_height = f.get_or<double>("dam_break.domain_height", std::max(s.domain_height, s.box_height), io::positive);
  if (s.domain_height < s.box_height) f.fail("dam_break.domain_height", "must be at least box_height");
  s.species = f.get<std::string>("dam_break.species");
  s.count = static_cast<std::size_t>(f.get<std::int64_t>("dam_break.count", io::positive));
  s.fill_height = f.get_or<double>("dam_break.fill_height", s.fill_height, io::positive);
  s.fill_growth = f.get_or<double>("dam_break.fill_growth", s.fill_growth, io::positive);
  s.gate_pulled = f.get_choice_or("dam_break.gate", "pulled", {"pulled", "removed"}) == "pulled";
  s.gate_acceleration = f.get_or<double>("dam_break.gate_acceleration", s.gate_acceleration, io::positive);
  s.gate_top_speed = f.get_or<double>("dam_break.gate_top_speed", s.gate_top_speed, io::positive);
  s.static_speed = f.get_or<double>("dam_break.static_speed", s.static_speed, io::positive);
  s.static_mean_speed = f.get_or<double>("dam_break.static_mean_speed", s.static_mean_speed, io::positive);
  s.settle_min_time = f.get_or<double>("dam_break.settle_min_time", s.settle_min_time, io::non_negative);
  s.settle_max_time = f.get_or<double>("dam_break.settle_max_time", s.settle_max_time, io::positive);
  if (s.settle_max_time < s.settle_min_time) f.fail("dam_break.settle_max_time", "must not be below settle_min_time");
  s.stop_speed = f.get_or<double>("dam_break.stop_speed", s.stop_speed, io::positive);
  s.stop_mean_speed = f.get_or<double>("dam_break.stop_mean_speed", s.stop_mean_speed, io::positive);
  s.collapse_min_time = f.get_or<double>("dam_break.collapse_min_time", s.collapse_min_time, io::non_negative);
  s.pixel = f.get_or<double>("dam_break.pixel", s.pixel, io::positive);
  if (f.has("dam_break.collapse_tangential")) {
    // Huet et al. 2021's two rules (Sec. V B) read the same contact parameters, so a column settled
    // under one collapses under the other. The elastic spring of Weinhart et al. 2012 reads others
    // (no clamp on the normal force, its own stiffness), which a switch mid-run would skip checking.
    constexpr TangentialModel kRules[] = {TangentialModel::memory, TangentialModel::memoryless};
    std::vector<std::string> names;
    for (TangentialModel m : kRules) names.push_back(tangential_model_name(m));
    const std::string rule = f.get_choice("dam_break.collapse_tangential", names);
    for (TangentialModel m : kRules)
      if (rule == tangential_model_name(m)) s.collapse_tangential = m;
    if (read_tangential_model(f) == TangentialModel::elastic_spring)
      f.fail("dam_break.collapse_tangential", "switches between the memory and memoryless rules only; this run's "
                                              "contacts keep the elastic_spring history (contact.tangential)");
  }
  return s;
}

Domain dam_break_domain(const DamBreakSetup& s) {
  Domain d;
  d.lo = {0, 0, 0};
  d.hi = {s.box_length, s.width, s.domain_height};
  return d;
}

DamBreakWalls add_dam_break_walls(World& world, const DamBreakSetup& s, int material) {
  auto plane = [&](const char* name, const Vec3& origin, const Vec3& normal) {
    Wall w;
    w.name = name;
    w.origin = origin;
    w.normal = normal;
    w.material = material;
    return world.add_wall(w);
  };
  DamBreakWalls walls;
  walls.floor = plane("floor", {0, 0, 0}, {0, 0, 1});
  walls.back = plane("back", {0, 0, 0}, {1, 0, 0});
  walls.end = plane("end", {s.box_length, 0, 0}, {-1, 0, 0});
  walls.side_lo = plane("side_y0", {0, 0, 0}, {0, 1, 0});
  walls.side_hi = plane("side_yW", {0, s.width, 0}, {0, -1, 0});

  // The gate is a rectangle as tall as the domain, so it holds the filling cloud too; it acts
  // only on particles whose centre is behind it, so nothing that flowed under it is pushed back.
  Wall gate;
  gate.name = "gate";
  gate.origin = {s.gate_position, 0.5 * s.width, 0.5 * s.domain_height};
  gate.normal = {-1, 0, 0};
  gate.material = material;
  gate.bounded = true;
  gate.axis_u = {0, 1, 0};
  gate.axis_v = cross(gate.normal, gate.axis_u);
  gate.half_extent_u = 0.5 * s.width + s.box_length;  // past the side walls: no edge inside the box
  gate.half_extent_v = 0.5 * s.domain_height;
  gate.motion.start_time = std::numeric_limits<double>::infinity();  // opened by the observer
  if (s.gate_pulled) {
    // Huet et al. 2021, Sec. III A: 43 m/s^2 up to 3 m/s.
    gate.motion.kind = WallMotion::Kind::accelerated;
    gate.motion.direction = {0, 0, 1};
    gate.motion.acceleration = s.gate_acceleration;
    gate.motion.top_speed = s.gate_top_speed;
  } else {
    gate.motion.kind = WallMotion::Kind::removed;
  }
  walls.gate = world.add_wall(gate);
  return walls;
}

void fill_dam_break(World& world, const DamBreakSetup& s, const ParticleInit& prototype, const CompositeShape* shape,
                    std::mt19937_64& rng) {
  BodyOverlapIndex index(prototype.radius);
  PlacedBody body;
  body.shape = shape;
  body.radius = prototype.radius;
  // A small clearance keeps the first contacts gentle: no body starts touching another.
  const double clearance = 1e-3 * prototype.radius;
  const Vec3 lo{clearance, clearance, clearance};
  const Vec3 size{s.gate_position - 2 * clearance, s.width - 2 * clearance, s.fill_height};
  const std::vector<PlacedBody> placed = insert_bodies_growing(index, body, s.count, lo, size, s.fill_growth, clearance,
                                                               rng, s.domain_height - 2 * clearance);
  world.reserve_particles(world.particles().owned + placed.size());
  for (const PlacedBody& b : placed) {
    ParticleInit p = prototype;
    p.position = b.position;
    p.orientation = b.orientation;
    world.add_particle(p);
  }
}

}  // namespace talus
