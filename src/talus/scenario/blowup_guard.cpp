#include "talus/scenario/blowup_guard.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "talus/io/json_file.h"
#include "talus/world/state_guard.h"

namespace talus {

namespace {

constexpr std::size_t kNamedParticles = 5;        ///< global ids in the one-line message
constexpr std::size_t kRecordedParticles = 1000;  ///< global ids in summary.json
constexpr std::size_t kDetailedParticles = 10;    ///< full particle states in summary.json

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);  // nan, inf and -inf print as such
  return buf;
}

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The offending particles' owned indices, by ascending global id.
std::vector<std::uint32_t> offenders(const World& world, StateFault fault) {
  const ParticleStore& p = world.particles();
  std::vector<std::uint32_t> found = particles_with(p, world.settings().domain, world.settings().time_step, fault);
  std::sort(found.begin(), found.end(), [&](std::uint32_t a, std::uint32_t b) { return p.gid[a] < p.gid[b]; });
  return found;
}

// "particle 17", "particles 3, 17", "particles 1, 2, 3, 4, 5 (and 12 others)".
std::string particle_list(const std::vector<std::uint32_t>& gids) {
  std::string s = gids.size() == 1 ? "particle " : "particles ";
  for (std::size_t k = 0; k < std::min(gids.size(), kNamedParticles); ++k)
    s += (k ? ", " : "") + std::to_string(gids[k]);
  if (gids.size() > kNamedParticles) s += " (and " + std::to_string(gids.size() - kNamedParticles) + " others)";
  return s;
}

// Which quantities are not finite, in the order a blow-up spreads: a force makes the velocity
// non-finite at the next kick, the velocity the position at the next drift.
std::vector<std::string> non_finite_quantities(const ParticleStore& p, const std::vector<std::uint32_t>& index) {
  std::vector<std::string> names;
  const std::pair<const char*, const std::vector<Vec3>*> quantities[] = {
      {"force", &p.force}, {"velocity", &p.velocity}, {"angular_velocity", &p.angular_velocity}, {"position", &p.position}};
  for (const auto& [name, values] : quantities)
    for (const std::uint32_t i : index)
      if (!finite((*values)[i])) {
        names.push_back(name);
        break;
      }
  return names;
}

std::string spoken(std::string name) {
  std::replace(name.begin(), name.end(), '_', ' ');
  return name;
}

std::string not_finite_text(const std::vector<std::string>& names) {
  std::string s;
  for (std::size_t k = 0; k < names.size(); ++k)
    s += (k == 0 ? "" : k + 1 == names.size() ? " and " : ", ") + spoken(names[k]);
  return s + (names.size() == 1 ? " is not finite" : " are not finite");
}

// Where particle i is outside: "on z (z = -0.51 m, domain.lo.z = 0 m)".
std::string outside_text(const World& world, std::uint32_t i) {
  const Domain& d = world.settings().domain;
  const Vec3 x = world.particles().position[i];
  const double r = world.particles().radius[i];
  for (int a = 0; a < 3; ++a) {
    if (d.periodic[a]) continue;
    const std::string axis(1, static_cast<char>('x' + a));
    if (x[a] < d.lo[a] - r)
      return "on " + axis + " (" + axis + " = " + number(x[a]) + " m, domain.lo." + axis + " = " + number(d.lo[a]) + " m)";
    if (x[a] > d.hi[a] + r)
      return "on " + axis + " (" + axis + " = " + number(x[a]) + " m, domain.hi." + axis + " = " + number(d.hi[a]) + " m)";
  }
  return "";
}

nlohmann::json vec_json(const Vec3& v) { return {v.x, v.y, v.z}; }

nlohmann::json particle_state(const ParticleStore& p, std::uint32_t i) {
  return {{"id", p.gid[i]},
          {"species", p.species[i]},
          {"fixed", p.is_fixed(i)},
          {"radius", p.radius[i]},
          {"mass", p.mass[i]},
          {"position", vec_json(p.position[i])},
          {"velocity", vec_json(p.velocity[i])},
          {"angular_velocity", vec_json(p.angular_velocity[i])},
          {"force", vec_json(p.force[i])},
          {"torque", vec_json(p.torque[i])}};
}

}  // namespace

namespace {
void put_text(ByteWriter& w, const std::string& text) {
  w.put(static_cast<std::uint64_t>(text.size()));
  for (const char c : text) w.put(c);
}

std::string get_text(ByteReader& r) {
  std::string text(r.get<std::uint64_t>(), ' ');
  for (char& c : text) c = r.get<char>();
  return text;
}

// Every rank stops when one does, each with the report of the lowest rank that found the fault.
std::optional<BlowUp> agree(const std::optional<BlowUp>& mine, const Communicator& comm) {
  std::vector<std::byte> out;
  ByteWriter w(out);
  w.put(static_cast<std::uint8_t>(mine.has_value()));
  if (mine) {
    w.put(mine->step);
    w.put(mine->time);
    put_text(w, mine->quantity);
    w.put(static_cast<std::uint64_t>(mine->particles.size()));
    for (const std::uint32_t id : mine->particles) w.put(id);
    put_text(w, mine->message);
    put_text(w, mine->particle_states.dump());
  }
  const std::vector<std::byte> all = comm.all_gather(out);
  ByteReader r(all);
  while (!r.done()) {
    if (!r.get<std::uint8_t>()) continue;
    BlowUp b;
    b.step = r.get<std::uint64_t>();
    b.time = r.get<double>();
    b.quantity = get_text(r);
    for (auto n = r.get<std::uint64_t>(); n > 0; --n) b.particles.push_back(r.get<std::uint32_t>());
    b.message = get_text(r);
    b.particle_states = nlohmann::json::parse(get_text(r));
    return b;
  }
  return std::nullopt;
}
}  // namespace

std::optional<BlowUp> BlowUpGuard::check(World& world) {
  const std::uint64_t before = removed_;
  std::optional<BlowUp> found = check_here(world);
  if (world.distributed()) {
    found = agree(found, world.communicator());
    // Particles that left some rank's slab of the domain: every rank rebuilds (collectively),
    // and the count is the whole system's.
    if (on_leave_ == LeavePolicy::remove) {
      const std::uint64_t here = removed_ - before;
      const std::uint64_t all = world.communicator().sum(here);
      removed_ = before + all;
      if (all > 0) world.rebuild_before_next_step();
    }
  }
  if (removed_ != before) world.make_ready();  // outputs and observers read contacts before the next step would rebuild
  return found;
}

std::optional<BlowUp> BlowUpGuard::check_here(World& world) {
  const ParticleStore& p = world.particles();
  const double dt = world.settings().time_step;
  const unsigned faults = scan_state(p, world.settings().domain, dt);
  if (faults == 0) return std::nullopt;
  if (faults == kOutside && on_leave_ == LeavePolicy::remove) {
    const GuardBounds bounds(world.settings().domain, dt);
    removed_ += world.remove_particles_if([&](std::size_t i) { return (particle_faults(p, i, bounds) & kOutside) != 0; });
    return std::nullopt;
  }

  // The worst fault decides what the message says: a non-finite state first, then motion no
  // step resolves, then a particle outside the domain.
  const StateFault worst = (faults & kNotFinite) ? kNotFinite
                           : (faults & kTooFast) ? kTooFast
                           : (faults & kSpinning) ? kSpinning
                                                  : kOutside;
  const std::vector<std::uint32_t> index = offenders(world, worst);
  const std::uint32_t first = index.front();
  BlowUp b;
  b.step = world.step_count();
  b.time = world.time();
  for (const std::uint32_t i : index) b.particles.push_back(p.gid[i]);
  std::string what;
  if (worst == kNotFinite) {
    const std::vector<std::string> names = non_finite_quantities(p, index);
    b.quantity = names.empty() ? "state" : names.front();
    what = not_finite_text(names);
  } else if (worst == kTooFast) {
    const Vec3 v = p.velocity[first];
    const double speed = std::hypot(v.x, v.y, v.z);  // no overflow to inf at 1e200 m/s
    b.quantity = "speed";
    what = "moves " + number(speed * dt / p.radius[first]) + " radii per step (speed " + number(speed) +
           " m/s, radius " + number(p.radius[first]) + " m, time step " + number(dt) + " s)";
  } else if (worst == kSpinning) {
    const Vec3 w = p.angular_velocity[first];
    const double spin = std::hypot(w.x, w.y, w.z);
    b.quantity = "spin";
    what = "turns " + number(spin * dt) + " rad per step (angular speed " + number(spin) + " rad/s, time step " +
           number(dt) + " s)";
  } else {
    b.quantity = "position";
    what = "left the domain " + outside_text(world, first);
  }
  b.message = "step " + std::to_string(b.step) + " (t = " + number(b.time) + " s): " + particle_list(b.particles) +
              ": " + what;
  b.particle_states = nlohmann::json::array();
  for (std::size_t k = 0; k < std::min(index.size(), kDetailedParticles); ++k)
    b.particle_states.push_back(particle_state(p, index[k]));
  return b;
}

nlohmann::json blow_up_json(const BlowUp& b) {
  const std::size_t recorded = std::min(b.particles.size(), kRecordedParticles);
  return io::non_finite_as_text({{"step", b.step},
                                 {"time", b.time},
                                 {"quantity", b.quantity},
                                 {"message", b.message},
                                 {"particle_count", b.particles.size()},
                                 {"particles", std::vector<std::uint32_t>(b.particles.begin(), b.particles.begin() + recorded)},
                                 {"particle_states", b.particle_states},
                                 {"state_file", kBlowUpStateFile}});
}

}  // namespace talus
