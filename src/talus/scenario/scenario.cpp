#include "talus/scenario/scenario.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "talus/contact/parameter_procedure.h"
#include "talus/io/number_format.h"
#include "talus/math/random_orientation.h"
#include "talus/parallel/communicator.h"
#include "talus/scenario/chute.h"
#include "talus/scenario/chute_study.h"
#include "talus/scenario/contact_reader.h"
#include "talus/scenario/dam_break.h"
#include "talus/scenario/dam_break_observer.h"
#include "talus/scenario/hopper_observer.h"
#include "talus/scenario/insertion.h"
#include "talus/scenario/particle_budget.h"
#include "talus/scenario/rigid_body_type.h"
#include "talus/scenario/shape_reader.h"
#include "talus/shape/convex_shape.h"
#include "talus/world/wall_clearance.h"

namespace talus {

namespace {

using io::ScenarioFile;

constexpr double kPi = std::numbers::pi;

struct SpeciesInfo {
  std::string name;
  double density = 0;  ///< kg/m^3
  double radius = 0;   ///< m, nominal (bounding radius of a shaped species)
  std::optional<RigidBodyType> body;  ///< set for non-spherical species
  int shape_index = 0;
  double mass() const { return body ? body->mass : density * 4.0 / 3.0 * kPi * radius * radius * radius; }
  double inertia() const { return body ? body->inertia.x : 0.4 * mass() * radius * radius; }
  // A particle of this species; spheres of radius r (the nominal radius when r = 0).
  ParticleInit particle(const Vec3& x, const Quat& q, int index, double r = 0) const {
    if (body) return rigid_particle(*body, shape_index, x, q, index);
    ParticleInit p;
    p.position = x;
    p.orientation = q;
    p.species = index;
    p.radius = r > 0 ? r : radius;
    p.mass = density * 4.0 / 3.0 * kPi * p.radius * p.radius * p.radius;
    const double i = 0.4 * p.mass * p.radius * p.radius;
    p.inertia = {i, i, i};
    return p;
  }
};

// [species.NAME]: its shape (shape_reader.h); a sphere's radius.
void read_shape(const ScenarioFile& f, const std::string& key, SpeciesInfo& s) {
  const std::optional<CompositeShape> body = read_body_shape(f, key);
  if (!body) {
    s.radius = f.get<double>(key + ".radius", io::positive);
    return;
  }
  s.body = make_rigid_body_type(*body, s.density);
  s.radius = s.body->radius;
}

// A density or size at the ends of the double range gives a mass or moment of inertia of 0,
// inf or nan, which the World refuses, or one whose square (in a reduced mass m_i m_j / (m_i +
// m_j)) is; no grain comes near these bounds. Reported with the key that gave the particle.
void check_mass(const ScenarioFile& f, const std::string& key, const SpeciesInfo& s, double r = 0) {
  const ParticleInit p = s.particle({}, {}, 0, r);
  for (double v : {p.mass, p.inertia.x, p.inertia.y, p.inertia.z})
    if (!(v >= 1e-150 && v <= 1e150))
      f.fail(key, "gives a particle of mass " + io::format_double(p.mass) + " kg and moments of inertia " +
                      io::format_double(p.inertia.x) + ", " + io::format_double(p.inertia.y) + ", " +
                      io::format_double(p.inertia.z) + " kg m^2: they must lie in [1e-150, 1e150]");
}

std::string indexed(const std::string& array, std::size_t k) { return array + "[" + std::to_string(k) + "]"; }

// The first of `names` in the first of `tables` holding it (the key read_contact took it from),
// else the first table: for messages.
std::string given_key(const ScenarioFile& f, const std::vector<std::string>& tables, const std::vector<std::string>& names) {
  for (const std::string& name : names)
    for (const std::string& t : tables)
      if (f.has(t + "." + name)) return t + "." + name;
  return tables.front();
}

// read_contact, plus the check the time step needs: a contact time, positive and finite.
// `between` names the two sides.
ContactParams read_timed_contact(const ScenarioFile& f, const std::vector<std::string>& tables, const ContactContext& ctx,
                                 const std::string& between) {
  const ContactParams c = read_contact(f, tables, ctx);
  const double m = ctx.reduced_mass;
  // A stiffness from max_overlap and impact_speed (Eq. 16) can overflow, or vanish.
  if (!(c.normal_stiffness > 0) || !std::isfinite(c.normal_stiffness))
    f.fail(given_key(f, tables, {"normal_stiffness", "max_overlap", "youngs_modulus"}),
           "gives the contact between " + between + " a stiffness of " + io::format_double(c.normal_stiffness));
  const double t = contact_duration(c, m, ctx.reduced_radius());
  if (!(t > 0) || !std::isfinite(t))
    f.fail(given_key(f, tables, {"normal_stiffness", "max_overlap", "youngs_modulus"}),
           "gives the contact between " + between + " no positive contact time (stiffness " +
               io::format_double(c.normal_stiffness) + ")");
  return c;
}

Domain read_domain(const ScenarioFile& f) {
  Domain d;
  d.lo = f.get<Vec3>("domain.lo");
  d.hi = f.get<Vec3>("domain.hi");
  for (int a = 0; a < 3; ++a) {
    if (!(d.hi[a] > d.lo[a])) f.fail("domain.hi", "must exceed domain.lo on every axis");
    // Finite ends, yet hi - lo may not be: every cell grid over the domain divides by it.
    if (!std::isfinite(d.length(a))) f.fail("domain.hi", "the extent hi - lo overflows a double");
  }
  const std::string periodic = f.get_or<std::string>("domain.periodic", "");
  for (char c : periodic) {
    if (c < 'x' || c > 'z') f.fail("domain.periodic", "expected a subset of \"xyz\", got \"" + periodic + "\"");
    d.periodic[c - 'x'] = true;
  }
  return d;
}

WallMotion read_motion(const ScenarioFile& f, const std::string& key) {
  WallMotion m;
  if (!f.has(key)) return m;
  const std::string kind = f.get_choice(key + ".kind", {"fixed", "removed", "accelerated"});
  m.start_time = f.get_or<double>(key + ".start_time", 0.0, io::non_negative);
  if (kind == "removed") m.kind = WallMotion::Kind::removed;
  if (kind == "accelerated") {
    m.kind = WallMotion::Kind::accelerated;
    m.direction = normalized_or_zero(f.get<Vec3>(key + ".direction"));
    if (norm2(m.direction) == 0) f.fail(key + ".direction", "must not be zero");
    m.acceleration = f.get<double>(key + ".acceleration", io::positive);
    m.top_speed = f.get<double>(key + ".top_speed", io::positive);
  }
  return m;
}

int material_index(std::vector<std::string>& materials, const std::string& name) {
  auto it = std::find(materials.begin(), materials.end(), name);
  if (it != materials.end()) return static_cast<int>(it - materials.begin());
  materials.push_back(name);
  return static_cast<int>(materials.size()) - 1;
}

void read_walls(const ScenarioFile& f, World& world, std::vector<std::string>& materials) {
  if (f.has("box")) {
    const Vec3 lo = f.get<Vec3>("box.lo"), hi = f.get<Vec3>("box.hi");
    for (int a = 0; a < 3; ++a)
      if (!(hi[a] > lo[a])) f.fail("box.hi", "must exceed box.lo on every axis");
    const int material = material_index(materials, f.get_or<std::string>("box.material", "wall"));
    const bool open_top = f.get_or<bool>("box.open_top", false);
    const char* names[6] = {"x-", "x+", "y-", "y+", "floor", "top"};
    for (int k = 0; k < 6; ++k) {
      if (k == 5 && open_top) continue;
      Wall w;
      w.name = names[k];
      w.normal = {};
      const int axis = k / 2;
      w.normal[axis] = (k % 2 == 0) ? 1 : -1;
      w.origin[axis] = (k % 2 == 0) ? lo[axis] : hi[axis];
      w.material = material;
      world.add_wall(w);
    }
  }
  const std::size_t n = f.array_size("walls");
  for (std::size_t k = 0; k < n; ++k) {
    const std::string key = indexed("walls", k);
    Wall w;
    w.name = f.get_or<std::string>(key + ".name", "wall" + std::to_string(k));
    w.origin = f.get<Vec3>(key + ".point");
    w.normal = normalized_or_zero(f.get<Vec3>(key + ".normal"));
    if (norm2(w.normal) == 0) f.fail(key + ".normal", "must not be zero");
    w.material = material_index(materials, f.get_or<std::string>(key + ".material", "wall"));
    if (f.has(key + ".half_extents")) {
      const std::vector<double> h = f.get<std::vector<double>>(key + ".half_extents", io::positive);
      if (h.size() != 2) f.fail(key + ".half_extents", "expected two half extents [along axis_u, along the other in-plane axis]");
      w.bounded = true;
      w.axis_u = f.get<Vec3>(key + ".axis_u");
      w.axis_u = normalized_or_zero(w.axis_u - dot(w.axis_u, w.normal) * w.normal);
      if (norm2(w.axis_u) == 0) f.fail(key + ".axis_u", "must not be parallel to the normal");
      w.axis_v = cross(w.normal, w.axis_u);
      w.half_extent_u = h[0];
      w.half_extent_v = h[1];
    }
    w.motion = read_motion(f, key + ".motion");
    world.add_wall(w);
  }
}

// run.processors = [px, py, pz]: the ranks of a run under mpirun along each axis, whole numbers
// whose product is the number of ranks (checked under mpirun only: on one rank the key has
// nothing to split).
RankCounts read_processors(const ScenarioFile& f, int ranks) {
  const Vec3 p = f.get<Vec3>("run.processors", io::positive);
  RankCounts counts{};
  int product = 1;
  for (int a = 0; a < 3; ++a) {
    if (p[a] != std::floor(p[a]) || p[a] > 1e6) f.fail("run.processors", "counts of ranks must be whole numbers");
    counts[a] = static_cast<int>(p[a]);
    product *= counts[a];
  }
  if (ranks > 1 && product != ranks)
    f.fail("run.processors", std::to_string(product) + " sub-domains for " + std::to_string(ranks) + " ranks (mpirun -n)");
  return counts;
}

}  // namespace

Scenario load_scenario(ScenarioFile& f, const ScenarioLimits& limits) {
  Scenario sc;
  ParticleBudget budget(f, limits.max_particles);
  RunControl& run = sc.control;
  run.end_time = f.get<double>("run.end_time", io::positive);
  run.output_interval = f.get_or<double>("run.output_interval", run.end_time / 100, io::positive);
  run.seed = static_cast<std::uint64_t>(f.get_or<std::int64_t>("run.seed", 1, io::non_negative));
  if (f.has("run.stop_kinetic_energy")) run.stop_kinetic_energy = f.get<double>("run.stop_kinetic_energy", io::positive);
  run.stop_min_time = f.get_or<double>("run.stop_min_time", 0.0, io::non_negative);
  run.vtk_interval = f.get_or<double>("run.vtk_interval", 0.0, io::non_negative);
  run.snapshot_interval = f.get_or<double>("run.snapshot_interval", 0.0, io::non_negative);
  run.checkpoint_interval = f.get_or<double>("run.checkpoint_interval", 0.0, io::non_negative);
  run.checkpoint_keep = static_cast<std::size_t>(f.get_or<std::int64_t>("run.checkpoint_keep", 3, io::positive));
  const double steps_per_contact = f.get_or<double>("run.steps_per_contact", 50, io::in_range(10, 1e9));
  if (f.has("run.processors")) run.processors = read_processors(f, Communicator::world().size());
  run.balance = f.get_choice_or("run.balance", "count", {"count", "neighbours"}) == "count" ? RankGrid::Balance::count
                                                                                         : RankGrid::Balance::neighbours;

  WorldSettings ws;
  ws.tangential_model = read_tangential_model(f);
  ws.particles_on_first_rank = limits.particles_on_first_rank;

  // Species.
  std::vector<SpeciesInfo> species;
  const bool chute = f.has("chute");
  if (chute) {
    species.push_back({"flow", 6 / kPi, 0.5, std::nullopt, 0});  // spheres: no rigid body type
    species.push_back({"base", 6 / kPi, 0.5, std::nullopt, 0});
  }
  for (const std::string& name : f.table_keys("species")) {
    const std::string key = "species." + name;
    SpeciesInfo s;
    s.name = name;
    s.density = f.get<double>(key + ".density", io::positive);
    read_shape(f, key, s);
    check_mass(f, key + ".density", s);
    species.push_back(s);
    // What `talus check` prints of each species: its mass properties, the centre of mass in
    // the frame its shape was given in.
    const Vec3 centre = s.body ? s.body->principal.position : Vec3{};
    const Vec3 moments = s.body ? s.body->inertia : Vec3{1, 1, 1} * s.inertia();
    sc.derived["species"][name] = {{"volume", s.body ? s.body->volume : 4.0 / 3.0 * kPi * std::pow(s.radius, 3)},
                                   {"mass", s.mass()},
                                   {"centre_of_mass", {centre.x, centre.y, centre.z}},
                                   {"principal_moments", {moments.x, moments.y, moments.z}},
                                   {"bounding_radius", s.radius}};
  }
  if (species.empty()) f.fail("species", "define at least one species, e.g. [species.glass] density = 2500, radius = 0.001");
  auto species_index = [&](const std::string& key) {
    const std::string name = f.get<std::string>(key);
    for (std::size_t s = 0; s < species.size(); ++s)
      if (species[s].name == name) return static_cast<int>(s);
    f.fail(key, "unknown species \"" + name + "\"");
  };

  std::unique_ptr<World> world;
  DamBreakWalls dam_walls;
  ChuteSetup chute_setup;
  if (chute) {
    chute_setup.length = f.get_or<double>("chute.length", 20, io::positive);
    chute_setup.width = f.get_or<double>("chute.width", 10, io::positive);
    chute_setup.base_diameter = f.get_or<double>("chute.base_diameter", 1, io::non_negative);
    chute_setup.fill_height = f.get_or<double>("chute.fill_height", 20, io::positive);
    chute_setup.angle_deg = f.get_or<double>("chute.angle", 24, io::in_range(0, 89));
    // Random sequential insertion jams near 0.38; the loosest bound keeps the column within the domain.
    chute_setup.initial_volume_fraction =
        f.get_or<double>("chute.initial_volume_fraction", chute_setup.initial_volume_fraction, io::in_range(0.1, 0.35));
    chute_setup.seed = run.seed;
    chute_setup.model = ws.tangential_model;
    chute_setup.particles_on_first_rank = ws.particles_on_first_rank;
    // Checked before the rough base settles in a box of the same size (make_rough_base), whose
    // World would refuse it: the periodic box must hold two interaction ranges.
    const double widest = std::max(chute_setup.diameter, chute_setup.base_diameter);
    if (chute_setup.length < 2.3 * widest) f.fail("chute.length", "periodic box narrower than two particle diameters plus skin");
    if (chute_setup.width < 2.3 * widest) f.fail("chute.width", "periodic box narrower than two particle diameters plus skin");
    budget.add("chute.fill_height", chute_particle_count_exact(chute_setup));
    if (chute_setup.base_diameter > 0)
      budget.add("chute.base_diameter",
                 rough_base_settled_count(chute_setup.length, chute_setup.width, chute_setup.base_diameter));
  }
  const bool dam_break = f.has("dam_break");
  DamBreakSetup dam;
  if (dam_break) {
    if (chute) f.fail("dam_break", "a scenario is either a chute or a dam break");
    dam = read_dam_break(f);
    budget.add("dam_break.count", static_cast<double>(dam.count));
  }
  if (!chute) {
    ws.domain = dam_break ? dam_break_domain(dam) : read_domain(f);
    ws.contact_manifold = f.get_or<bool>("contact.manifold", false);
    ws.narrow_phase_reuse = f.get_or<bool>("contact.narrow_phase_reuse", true);
    ws.manifold_refit = f.get_or<double>("contact.manifold_refit", 0.0);
    ws.gjk_warm_start = f.get_or<bool>("contact.gjk_warm_start", true);
    if (!(ws.manifold_refit >= 0 && ws.manifold_refit <= 0.5))
      f.fail("contact.manifold_refit", "must be a fraction of the overlap in [0, 0.5]");
    // Recycled points by default wherever they can be had: the dam-break ensembles gave the same
    // regimes, runouts and heights within their scatter (validation/REPORT.md).
    ws.manifold_recycle = f.get_or<double>(
        "contact.manifold_recycle", default_manifold_recycle(ws.contact_manifold, ws.narrow_phase_reuse, ws.manifold_refit));
    if (!(ws.manifold_recycle >= 0 && ws.manifold_recycle <= 1e-3))
      f.fail("contact.manifold_recycle", "must be a travel in [0, 1e-3] m");
    if (ws.manifold_recycle > 0 && !(ws.contact_manifold && ws.narrow_phase_reuse))
      f.fail("contact.manifold_recycle", "needs contact.manifold = true and contact.narrow_phase_reuse = true");
    if (ws.manifold_recycle > 0 && ws.manifold_refit > 0)
      f.fail("contact.manifold_recycle", "excludes contact.manifold_refit: set one of the two");
    ws.gravity = f.get_or<Vec3>("domain.gravity", Vec3{0, 0, -9.81});
  }
  // Also for the chute and the dam break, which build their own domains (non-periodic in z, and
  // on every axis).
  if (f.get_choice_or("domain.on_leave", "error", {"error", "delete"}) == "delete") run.on_leave = LeavePolicy::remove;

  // Contact parameters for every pair of species and every wall material.
  std::vector<std::string> materials;
  if (dam_break) material_index(materials, "wall");
  if (!chute) {
    // Walls first: they name the materials.
    World probe(ws);
    read_walls(f, probe, materials);
  }
  if (materials.empty()) materials.push_back("wall");
  ContactTable table;
  table.resize(static_cast<int>(species.size()), static_cast<int>(materials.size()));
  const std::size_t pair_overrides = f.array_size("contact.pair");
  for (std::size_t a = 0; a < species.size(); ++a)
    for (std::size_t b = a; b < species.size(); ++b) {
      std::vector<std::string> tables = {"contact"};
      for (std::size_t k = 0; k < pair_overrides; ++k) {
        const std::string key = indexed("contact.pair", k);
        const std::vector<std::string> names = {f.get<std::string>(key + ".species[0]"), f.get<std::string>(key + ".species[1]")};
        if ((names[0] == species[a].name && names[1] == species[b].name) ||
            (names[1] == species[a].name && names[0] == species[b].name))
          tables.insert(tables.begin(), key);
      }
      ContactContext ctx{species[a].mass() * species[b].mass() / (species[a].mass() + species[b].mass()),
                         species[a].radius, species[a].inertia(), species[b].radius, species[b].inertia(),
                         ws.tangential_model, false, species[a].body || species[b].body};
      table.set_pair(static_cast<int>(a), static_cast<int>(b),
                     read_timed_contact(f, tables, ctx, "species \"" + species[a].name + "\" and \"" + species[b].name + "\""));
    }
  for (std::size_t a = 0; a < species.size(); ++a)
    for (std::size_t m = 0; m < materials.size(); ++m) {
      ContactContext ctx{species[a].mass(), species[a].radius, species[a].inertia(), 0, 0, ws.tangential_model, true,
                         species[a].body.has_value()};
      table.set_wall(static_cast<int>(a), static_cast<int>(m),
                     read_timed_contact(f, {"contact.wall", "contact"}, ctx,
                                        "species \"" + species[a].name + "\" and wall material \"" + materials[m] + "\""));
    }

  // Time step: given, or t_c / steps_per_contact; never above t_c / 10.
  double tc_min = 1e300;
  for (std::size_t a = 0; a < species.size(); ++a) {
    for (std::size_t b = a; b < species.size(); ++b) {
      const double m = species[a].mass() * species[b].mass() / (species[a].mass() + species[b].mass());
      const double r = species[a].radius * species[b].radius / (species[a].radius + species[b].radius);
      tc_min = std::min(tc_min, contact_duration(table.pair(static_cast<int>(a), static_cast<int>(b)), m, r));
    }
    for (std::size_t mt = 0; mt < materials.size(); ++mt) {
      tc_min = std::min(tc_min, contact_duration(table.wall(static_cast<int>(a), static_cast<int>(mt)), species[a].mass(),
                                                 species[a].radius));
    }
  }
  ws.time_step = f.get_or<double>("run.time_step", tc_min / steps_per_contact, io::positive);
  if (ws.time_step > tc_min / 10)
    f.fail("run.time_step", "above t_c/10 = " + std::to_string(tc_min / 10) + " s (shortest contact time t_c = " +
                                std::to_string(tc_min) + " s)");
  sc.derived["contact_time"] = tc_min;
  sc.derived["time_step"] = ws.time_step;
  sc.derived["steps_per_contact"] = tc_min / ws.time_step;

  if (chute) {
    chute_setup.flow = table.pair(0, 0);
    chute_setup.base = table.pair(0, 1);
    chute_setup.time_step = ws.time_step;
    world = build_chute(chute_setup);
  } else {
    world = std::make_unique<World>(ws);
    if (dam_break) dam_walls = add_dam_break_walls(*world, dam, material_index(materials, "wall"));
    read_walls(f, *world, materials);
    for (SpeciesInfo& s : species)
      if (s.body) s.shape_index = world->add_shape(s.body->shape);
  }
  world->contacts() = table;

  // Particles: explicit, then random insertion regions.
  const Domain& domain = world->settings().domain;
  const double cell = 2 * std::max_element(species.begin(), species.end(), [](auto& a, auto& b) {
                        return a.radius < b.radius;
                      })->radius;
  SphereOverlapIndex index(domain.lo, domain.hi, domain.periodic, cell);
  for (std::size_t i = 0; i < world->particles().owned; ++i)
    index.insert({world->particles().position[i], world->particles().radius[i]});
  auto inside = [&](const Vec3& x) {
    for (int a = 0; a < 3; ++a)
      if (!domain.periodic[a] && (x[a] < domain.lo[a] || x[a] > domain.hi[a])) return false;
    return true;
  };
  const std::size_t explicit_count = f.array_size("particles");
  budget.add("particles", static_cast<double>(explicit_count));
  for (std::size_t k = 0; k < explicit_count; ++k) {
    const std::string key = indexed("particles", k);
    const int s = species_index(key + ".species");
    const Vec3 position = f.get<Vec3>(key + ".position");
    if (!inside(position)) f.fail(key + ".position", "outside the domain");
    Quat q;
    if (f.has(key + ".orientation")) {
      const std::vector<double> v = f.get<std::vector<double>>(key + ".orientation");
      if (v.size() != 4 || v[0] * v[0] + v[1] * v[1] + v[2] * v[2] + v[3] * v[3] == 0)
        f.fail(key + ".orientation", "expected a quaternion [w, x, y, z]");
      q = Quat{v[0], v[1], v[2], v[3]}.normalized();
    }
    const double radius = species[s].body ? 0.0 : f.get_or<double>(key + ".radius", species[s].radius, io::positive);
    check_mass(f, key + ".radius", species[s], radius);
    ParticleInit p = species[s].particle(position, q, s, radius);
    p.velocity = f.get_or<Vec3>(key + ".velocity", Vec3{});
    p.angular_velocity = f.get_or<Vec3>(key + ".angular_velocity", Vec3{});
    p.fixed = f.get_or<bool>(key + ".fixed", false);
    if (index.overlaps({p.position, p.radius})) f.fail(key + ".position", "overlaps another particle");
    index.insert({p.position, p.radius});
    world->add_particle(p);
  }
  std::mt19937_64 rng(run.seed);
  const std::size_t inserts = f.array_size("insert");
  for (std::size_t k = 0; k < inserts; ++k) {
    const std::string key = indexed("insert", k);
    const int s = species_index(key + ".species");
    const auto count = static_cast<std::size_t>(f.get<std::int64_t>(key + ".count", io::non_negative));
    budget.add(key + ".count", static_cast<double>(count));
    const Vec3 lo = f.get<Vec3>(key + ".region_lo"), hi = f.get<Vec3>(key + ".region_hi");
    for (int a = 0; a < 3; ++a)
      if (!(hi[a] > lo[a])) f.fail(key + ".region_hi", "must exceed region_lo on every axis");
    if (!inside(lo) || !inside(hi)) f.fail(key + ".region_hi", "insertion region outside the domain");
    const double growth = f.get_or<double>(key + ".growth", 0.0, io::non_negative);
    const double r_min = f.get_or<double>(key + ".radius_min", species[s].radius, io::positive);
    const double r_max = f.get_or<double>(key + ".radius_max", species[s].radius, io::positive);
    if (r_max < r_min) f.fail(key + ".radius_max", "must not be below radius_min");
    check_mass(f, key + ".radius_min", species[s], r_min);
    check_mass(f, key + ".radius_max", species[s], r_max);
    const Vec3 velocity = f.get_or<Vec3>(key + ".velocity", Vec3{});
    const std::size_t first = index.spheres().size();
    try {
      insert_growing(index, count, lo, hi - lo, growth,
                     [&](std::mt19937_64& g) { return r_min + (r_max - r_min) * std::uniform_real_distribution<double>(0, 1)(g); },
                     rng, domain.hi.z - lo.z, 100000, [&](const PlacedSphere& sp) {
                       return sphere_cuts_a_wall(world->walls(), 0, sp.centre, sp.radius);
                     });
    } catch (const std::runtime_error& e) {
      f.fail(key + ".count", std::string(e.what()) + "; enlarge the region or set growth");
    }
    for (std::size_t q = first; q < index.spheres().size(); ++q) {
      const PlacedSphere& sp = index.spheres()[q];
      ParticleInit p = species[s].particle(sp.centre, species[s].body ? random_orientation(rng) : Quat{}, s, sp.radius);
      p.velocity = velocity;
      world->add_particle(p);
    }
  }
  if (dam_break) {
    const int s = species_index("dam_break.species");
    const CompositeShape* shape = species[s].body ? &world->shapes()[species[s].shape_index] : nullptr;
    try {
      fill_dam_break(*world, dam, species[s].particle({}, {}, s), shape, rng);
    } catch (const std::runtime_error& e) {
      f.fail("dam_break.count", std::string(e.what()) + "; raise dam_break.domain_height or lower the count");
    }
    sc.observers.push_back(std::make_unique<DamBreakObserver>(dam, dam_walls));
  }
  if (f.has("hopper")) sc.observers.push_back(std::make_unique<HopperObserver>(read_hopper(f, domain.lo, domain.hi)));
  const std::size_t pour_count = f.array_size("pour");
  for (std::size_t k = 0; k < pour_count; ++k) {
    const std::string key = indexed("pour", k);
    PourSpec p;
    p.species = species_index(key + ".species");
    p.density = species[p.species].density;
    p.total = static_cast<std::size_t>(f.get<std::int64_t>(key + ".count", io::positive));
    budget.add(key + ".count", static_cast<double>(p.total));
    // No batch can pour more than the total; a larger one only multiplied the attempts (20 per
    // particle of the batch) drawn in a full region.
    p.batch = std::min(p.total, static_cast<std::size_t>(f.get<std::int64_t>(key + ".batch", io::positive)));
    p.interval = f.get<double>(key + ".interval", io::positive);
    p.start_time = f.get_or<double>(key + ".start_time", 0.0, io::non_negative);
    p.region_lo = f.get<Vec3>(key + ".region_lo");
    p.region_hi = f.get<Vec3>(key + ".region_hi");
    for (int a = 0; a < 3; ++a)
      if (!(p.region_hi[a] > p.region_lo[a])) f.fail(key + ".region_hi", "must exceed region_lo on every axis");
    if (!inside(p.region_lo) || !inside(p.region_hi)) f.fail(key + ".region_hi", "pouring region outside the domain");
    p.radius_min = f.get_or<double>(key + ".radius_min", species[p.species].radius, io::positive);
    p.radius_max = f.get_or<double>(key + ".radius_max", species[p.species].radius, io::positive);
    if (p.radius_max < p.radius_min) f.fail(key + ".radius_max", "must not be below radius_min");
    check_mass(f, key + ".radius_min", species[p.species], p.radius_min);
    check_mass(f, key + ".radius_max", species[p.species], p.radius_max);
    p.velocity = f.get_or<Vec3>(key + ".velocity", Vec3{});
    if (species[p.species].body) {
      p.rigid = true;
      p.prototype = species[p.species].particle({}, {}, p.species);
      p.radius_min = p.radius_max = species[p.species].radius;
    }
    sc.pours.emplace_back(p, run.seed + 1000 + k);
  }
  if (world->particles_added() == 0) {
    if (sc.pours.empty()) f.fail("particles", "the scenario has no particles (add [[particles]], [[insert]] or [[pour]])");
    sc.pours.front().pour_due(*world);
  }

  // A periodic box must hold two interaction ranges.
  double r_max = 0;
  for (std::size_t i = 0; i < world->particles().owned; ++i) r_max = std::max(r_max, world->particles().radius[i]);
  for (int a = 0; a < 3; ++a)
    if (domain.periodic[a] && domain.length(a) < 2 * (2.3 * r_max))
      f.fail(chute ? "chute" : "domain.hi", "periodic box narrower than two particle diameters plus skin");

  if (chute) {
    ChuteStudyConfig study = read_chute_study(f, tc_min, run.end_time, chute_setup.fill_height,
                                              chute_setup.base_diameter, chute_setup.density);
    study.time_step = world->settings().time_step;
    sc.observers.push_back(make_chute_observer(study));
  }
  f.check_no_unknown_keys();
  for (const auto& s : species) sc.species.push_back(s.name);
  sc.wall_materials = materials;
  sc.derived["particles"] = world->particles_added();
  sc.derived["walls"] = world->walls().size();
  sc.derived["expected_memory_bytes"] = world->particles_added() * 400;  // measured engine footprint per particle, with margin
  sc.world = std::move(world);
  return sc;
}

}  // namespace talus
