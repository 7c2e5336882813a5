// Every example under every sub-model combination of the contact law (docs/contact_models.md)
// either runs or is refused with `FILE:LINE: KEY: message` (or `--set KEY: message`), as
// `talus check --set ...` would print it (issue 24, item 4).
//
// For each examples/*.toml (globbed at run time, shrunk by overrides that keep its nature) and
// each combination, the sub-model keys are applied as `--set` overrides (the "--set" row). If
// the example loads, it runs 200 steps twice: from its initial state, and from a contact-rich
// state (the same bodies, put where the linear example has settled into contacts: most
// examples start as a dilute cloud and would touch nothing in 200 steps). After each, every
// position, velocity, angular velocity and energy must be finite, no body may have moved more
// than three radii nor overlap by a quarter of one, and kinetic plus elastic energy may not
// have grown beyond the work of gravity (by 5 % of its scale). If the example is refused, the
// message must have the form above. A refusal often only says that the example's own keys do
// not fit the combination (normal_stiffness under Hertz, friction under tangential = "none"):
// overrides cannot delete keys. Such a combination is then tried again on an "edited" copy of
// the example, whose [contact] tables have those keys commented out (line numbers kept) and
// their equivalents set by overrides (the "edit" row): tangential_stiffness from the ratio,
// tangential_damping_ratio from the linear dashpots, normal_restitution or normal_damping_rate
// for the Hertz dashpot, a rolling_friction of 0.1 where the example has none.
//
// Hertz moduli: per example, from the linear contact of its first mobile species, E* such
// that the elastic Hertz impact at impact_speed lasts as long as the linear one,
// t_c = 2.868 (m*^2 / (R* E*^2 v))^(1/5) = pi sqrt(m* / k_n), with nu = 0.3; impact_speed is
// the example's own, else 1 (m/s, or sqrt(g d) in chute units).
//
// Combinations per example (72):
//   normal linear:  tangential (5) x rolling (2) x normal_clamp (2)                  = 20
//   normal hertz:   damping viscous|tsuji (2) x tangential (5) x rolling (2) x clamp (2) = 40
//   shorthand model = memory | memoryless | elastic_spring                              =  3
//   restitution_damping = solved | eq11                                                 =  2
//   [contact.wall] alone: tangential (5), normal = hertz, hertz + mindlin               =  7
// 10 examples x 72, plus a rough-base chute under 4 of them: 724 loads by --set, and an edited
// load for most refusals. Expected: every sphere example runs every normal x tangential x rolling
// x clamp x damping combination (--set or edited); a shaped example (boxes, crosses) runs exactly
// the linear ones without Mindlin and rolling, and refuses the rest naming spheres; a
// [contact.wall] history rule other than the run's is refused as "one history rule per run";
// the shorthand runs as is. The summary gives per example the counts, the contact-rich state
// (steps of the linear run, contacts), the fewest contacts left after a run from it, the
// largest travel and overlap (radii) and energy gain (of its scale), and the seconds taken.
//
// The later tests pin the bugs the grid found: memoryless refusing the spring models' keys, the
// time step of heavily damped contacts, the flat-base chute's start.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "talus/io/input_error.h"
#include "talus/io/scenario_file.h"
#include "talus/scenario/chute.h"
#include "talus/scenario/contact_reader.h"
#include "talus/scenario/scenario.h"

namespace talus {
namespace {

namespace fs = std::filesystem;

constexpr int kSteps = 200;
constexpr std::uint64_t kRichSteps = 100000;
constexpr double kPoisson = 0.3;

// Overrides that shrink an example and keep its nature (a few hundred bodies at most; the
// study observers are not run, only World::run). The chute's rough base is settled by a run of
// its own at every load (make_rough_base: 83 s at 10 x 5, 0.4 s at 3 x 2.5), so the grid runs
// on the flat base (base_diameter = 0, a wall: Weinhart et al. 2012 vary lambda down to 0) and
// a 3 x 2.5 rough-base chute runs a few combinations (kRoughBase).
struct Variant {
  std::string suffix;               ///< "" for the example's own row
  std::vector<std::string> shrink;  ///< overrides
  bool full_grid = true;            ///< every combination, else kRoughBase only
};
const std::map<std::string, std::vector<Variant>> kShrink = {
    {"chute",
     {{"", {"chute.fill_height=2", "chute.length=10", "chute.width=5", "chute.base_diameter=0"}},
      {"(rough)", {"chute.fill_height=2", "chute.length=3", "chute.width=2.5"}, false}}},
    {"cross_pile", {{"", {"insert[0].count=40", "insert[0].region_hi=[0.185, 0.185, 0.08]"}}}},
    {"dam_break_crosses", {{"", {"dam_break.count=60", "dam_break.fill_height=0.05"}}}},
    {"dam_break_small", {{"", {"dam_break.count=40", "dam_break.fill_height=0.05"}}}},
    {"dam_break_spheres", {{"", {"dam_break.count=100"}}}},
    {"hopper",  // just above the plug
     {{"", {"insert[0].count=100", "insert[0].region_lo=[0.075, 0.0, 0.0715]", "insert[0].region_hi=[0.085, 0.008, 0.1]"}}}},
    {"settling_box", {{"", {"insert[0].count=200"}}}},
};
const std::set<std::string> kRoughBase = {"linear elastic_spring roll=none clamp=false", "linear memory roll=huet clamp=true",
                                          "hertz/tsuji mindlin roll=huet clamp=true",
                                          "hertz/viscous elastic_spring roll=none clamp=false"};

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string number(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", x);
  return buf;
}

// One combination: the keys it sets, by override.
struct Combination {
  std::string label;
  std::vector<std::string> keys;  ///< KEY=VALUE
  // What it chooses for the contact law ("" = the example's own).
  std::string normal, damping, tangential, rolling;
  bool main = false;               ///< one of the normal x tangential x rolling x clamp x damping grid
  bool wall_only = false;          ///< set in [contact.wall] only
  bool hertz() const { return normal == "hertz"; }
  bool mindlin() const { return tangential == "mindlin"; }
};

std::vector<Combination> combinations() {
  std::vector<Combination> out;
  const char* tangentials[] = {"memory", "elastic_spring", "mindlin", "memoryless", "none"};
  for (const char* normal : {"linear", "hertz"})
    for (const char* damping : {"viscous", "tsuji"}) {
      const bool hertz = std::string(normal) == "hertz";
      if (!hertz && std::string(damping) == "tsuji") continue;  // a linear spring's dashpot is the same either way
      for (const char* tangential : tangentials)
        for (const char* rolling : {"none", "huet"})
          for (const char* clamp : {"true", "false"}) {
            Combination c;
            c.normal = normal;
            c.damping = hertz ? damping : "";
            c.tangential = tangential;
            c.rolling = rolling;
            c.main = true;
            c.label = std::string(normal) + (hertz ? "/" + std::string(damping) : "") + " " + tangential + " roll=" +
                      rolling + " clamp=" + clamp;
            c.keys = {"contact.normal=" + std::string(normal), "contact.tangential=" + std::string(tangential),
                      "contact.rolling=" + std::string(rolling), "contact.normal_clamp=" + std::string(clamp)};
            if (hertz) c.keys.push_back("contact.damping=" + std::string(damping));
            out.push_back(c);
          }
    }
  for (const char* model : {"memory", "memoryless", "elastic_spring"}) {
    Combination c;
    c.label = std::string("model=") + model;
    c.keys = {"contact.model=" + std::string(model)};
    out.push_back(c);
  }
  for (const char* formula : {"solved", "eq11"}) {
    Combination c;
    c.label = std::string("restitution_damping=") + formula;
    c.keys = {"contact.restitution_damping=" + std::string(formula)};
    out.push_back(c);
  }
  for (const char* tangential : tangentials) {
    Combination c;
    c.label = std::string("wall: ") + tangential;
    c.keys = {"contact.wall.tangential=" + std::string(tangential)};
    c.tangential = tangential;
    c.wall_only = true;
    out.push_back(c);
  }
  for (const bool mindlin : {false, true}) {
    Combination c;
    c.label = mindlin ? "wall: hertz mindlin" : "wall: hertz";
    c.keys = {"contact.wall.normal=hertz"};
    if (mindlin) c.keys.push_back("contact.wall.tangential=mindlin");
    c.normal = "hertz";
    c.tangential = mindlin ? "mindlin" : "";
    c.wall_only = true;
    out.push_back(c);
  }
  return out;
}

// A body's state, to continue an example from where its linear run has contacts.
struct BodyState {
  Vec3 position, velocity, angular_velocity;
  Quat orientation;
  double radius = 0;
};
using State = std::map<std::uint32_t, BodyState>;  // by global id

// An example, shrunk, with what its linear contact is.
struct Example {
  std::string name;                 ///< file stem
  std::string display;              ///< examples/NAME.toml
  std::string text;
  std::vector<std::string> shrink;  ///< overrides
  bool shaped = false;
  TangentialModel rule = TangentialModel::memory;  ///< the run's history rule
  std::set<std::string> contact_keys;  ///< keys of [contact]
  // The linear contact of the first mobile species with itself, and its Hertz equivalent.
  double reduced_mass = 0, reduced_radius = 0;
  double kn = 0, eta_n = 0, kt = 0, eta_t = 0;
  double impact_speed = 1, youngs_modulus = 0;
  State rich;                       ///< the linear example once it has contacts
  std::uint64_t rich_steps = 0;     ///< steps it took
  std::size_t rich_contacts = 0;
  bool has(const std::string& key) const { return contact_keys.contains(key); }
};

State state_of(const World& w) {
  State s;
  const ParticleStore& p = w.particles();
  for (std::size_t i = 0; i < p.owned; ++i)
    s[p.gid[i]] = {p.position[i], p.velocity[i], p.angular_velocity[i], p.orientation[i], p.radius[i]};
  return s;
}

// Puts every body of `w` into `s`; false if the bodies are not the same (a load is deterministic).
bool set_state(World& w, const State& s) {
  ParticleStore& p = w.particles_mutable();
  if (p.owned != s.size()) return false;
  for (std::size_t i = 0; i < p.owned; ++i) {
    const auto it = s.find(p.gid[i]);
    if (it == s.end() || it->second.radius != p.radius[i]) return false;
    p.position[i] = it->second.position;
    p.velocity[i] = it->second.velocity;
    p.angular_velocity[i] = it->second.angular_velocity;
    p.orientation[i] = it->second.orientation;
  }
  return true;
}

std::size_t contacts_of(const World& w) {
  const Diagnostics d = w.diagnostics();
  return d.contacts + d.wall_contacts;
}

struct Outcome {
  bool ran = false;
  std::string message;              ///< the InputError, or what went wrong in the run
  bool failed = false;              ///< crash, NaN, blow-up: an engine or reader bug
  double max_travel = 0;            ///< largest displacement over the radius
  double energy_gain = -1e300;      ///< (E_1 - E_0) / energy scale, largest of the runs
  double max_overlap = 0;           ///< largest overlap over the radius after a run
  std::size_t contacts = 0;         ///< contacts (particle and wall) after the run from the contact-rich state
};

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

const std::regex kErrorLine(R"(^([^:\s]+:[0-9]+: [A-Za-z0-9_.\[\]]+|--set [A-Za-z0-9_.\[\]]+): \S.*$)");

bool well_formed(const std::string& message) {
  if (message.empty()) return false;
  std::istringstream lines(message);
  for (std::string line; std::getline(lines, line);)
    if (!std::regex_match(line, kErrorLine)) return false;
  return true;
}

// Runs kSteps steps of `w` and checks the state; returns "" or what went wrong.
std::string run_and_check(World& w, Outcome& out) {
  w.capture_state();  // prepares the world: contacts and their energy at the start
  const ParticleStore& p = w.particles();
  std::map<std::uint32_t, Vec3> start;
  for (std::size_t i = 0; i < p.owned; ++i) start[p.gid[i]] = p.position[i];
  const Diagnostics d0 = w.diagnostics();
  try {
    w.run(kSteps);
  } catch (const std::exception& e) {
    return std::string("exception in the run: ") + e.what();
  }
  const Diagnostics d1 = w.diagnostics();
  const Vec3 g = w.settings().gravity;
  double gravity_work = 0;  // -delta of the potential energy, from unwrapped displacements
  double travel = 0;
  std::size_t bad = 0;
  for (std::size_t i = 0; i < p.owned; ++i) {
    if (!finite(p.position[i]) || !finite(p.velocity[i]) || !finite(p.angular_velocity[i])) {
      ++bad;
      continue;
    }
    if (p.is_fixed(i)) continue;
    const Vec3 dx = w.settings().domain.minimum_image(p.position[i] - start.at(p.gid[i]));
    travel = std::max(travel, norm(dx) / p.radius[i]);
    gravity_work += p.mass[i] * dot(g, dx);
  }
  const double energies[] = {d1.kinetic_translational, d1.kinetic_rotational, d1.elastic_normal,
                             d1.elastic_tangential,    d1.elastic_rolling,    d1.gravitational,
                             d1.max_overlap_ratio,     d1.max_speed,          d1.max_angular_speed};
  const bool energies_finite = std::all_of(std::begin(energies), std::end(energies), [](double x) { return std::isfinite(x); });
  const double e0 = d0.kinetic() + d0.elastic(), e1 = d1.kinetic() + d1.elastic();
  const double scale = std::max({e0, e1, std::abs(gravity_work), 1e-300});
  const double gain = (e1 - e0 - gravity_work) / scale;
  out.max_travel = std::max(out.max_travel, travel);
  out.max_overlap = std::max(out.max_overlap, d1.max_overlap_ratio);
  out.energy_gain = std::max(out.energy_gain, gain);
  if (bad > 0) return std::to_string(bad) + " particles with a non-finite position, velocity or angular velocity";
  if (!energies_finite) return "non-finite energy in World::diagnostics()";
  if (travel > 3) return "blow-up: a particle moved " + number(travel) + " radii in " + std::to_string(kSteps) + " steps";
  if (d1.max_overlap_ratio > 0.25) return "blow-up: overlap " + number(d1.max_overlap_ratio) + " radii";
  // The contacts dissipate: kinetic plus elastic energy grows by the work of gravity at most.
  if (gain > 0.05) return "energy grew by " + number(100 * gain) + " % of its scale";
  return "";
}

// Loads `text` with `overrides`; if it loads, runs kSteps steps from the loaded state and kSteps
// from `rich` (the linear example's state once it has contacts, put into a fresh load), and
// checks both.
Outcome load_and_run(const std::string& text, const std::string& display, const std::vector<std::string>& overrides,
                     const State& rich) {
  Outcome out;
  auto load = [&] {
    io::ScenarioFile f = io::ScenarioFile::from_string(text, display);
    for (const std::string& o : overrides) f.set_override(o);
    return load_scenario(f);
  };
  Scenario sc;
  try {
    sc = load();
  } catch (const io::InputError& e) {
    out.message = e.what();
    return out;
  } catch (const std::exception& e) {
    out.failed = true;
    out.message = std::string("exception other than InputError while loading: ") + e.what();
    return out;
  }
  out.ran = true;
  std::string problem = run_and_check(*sc.world, out);
  if (problem.empty()) {
    Scenario again = load();
    if (!set_state(*again.world, rich)) {
      problem = "a second load gave other bodies";
    } else {
      problem = run_and_check(*again.world, out);
      if (!problem.empty()) problem = "from the contact-rich state: " + problem;
      out.contacts = contacts_of(*again.world);
    }
  }
  if (!problem.empty()) {
    out.failed = true;
    out.message = problem;
  }
  return out;
}

// The example's [contact] tables with `keys` commented out; line numbers are kept. A table left
// empty goes too (an empty table is reported as an unknown key).
std::string without_contact_keys(const std::string& text, const std::set<std::string>& keys) {
  static const std::regex header(R"(^\s*\[\[?\s*([A-Za-z0-9_.]+)\s*\]\]?.*$)");
  static const std::regex assignment(R"(^\s*([A-Za-z0-9_]+)\s*=.*$)");
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  bool in_contact = false;
  std::size_t open = lines.size();  // header line of the contact table being read
  bool kept = false;                // whether it keeps an assignment
  auto close = [&] {
    if (open < lines.size() && !kept) lines[open] = "# (emptied by the test) " + lines[open];
    open = lines.size();
  };
  for (std::size_t k = 0; k < lines.size(); ++k) {
    std::smatch m;
    if (std::regex_match(lines[k], m, header)) {
      close();
      in_contact = m[1] == "contact" || m[1].str().starts_with("contact.");
      if (in_contact) open = k, kept = false;
    } else if (in_contact && std::regex_match(lines[k], m, assignment)) {
      if (keys.contains(m[1]))
        lines[k] = "# (removed by the test) " + lines[k];
      else
        kept = true;
    }
  }
  close();
  std::string out;
  for (const auto& line : lines) out += line + "\n";
  return out;
}

// The edited copy of the example for a combination: keys it does not take removed, their
// equivalents set. Empty `removed` and `added` when there is nothing to edit.
struct Edit {
  std::set<std::string> removed;
  std::vector<std::string> added;  ///< KEY=VALUE overrides
  std::string summary() const {
    std::string s;
    for (const auto& k : removed) s += (s.empty() ? "-" : " -") + k;
    for (const auto& a : added) s += (s.empty() ? "+" : " +") + a.substr(std::string("contact.").size());
    return s;
  }
};

Edit edit_for(const Example& ex, const Combination& c) {
  Edit e;
  if (!c.main) return e;
  auto remove = [&](std::initializer_list<const char*> keys) {
    for (const char* k : keys)
      if (ex.has(k)) e.removed.insert(k);
  };
  const bool none = c.tangential == "none";
  bool damping_ratio = false;  // eta_t as a ratio to eta_n
  if (c.hertz()) {
    remove({"normal_stiffness", "max_overlap", "restitution_damping", "tangential_stiffness_ratio",
            "tangential_restitution"});
    if (c.damping == "tsuji") {
      remove({"normal_damping", "normal_damping_rate", "normal_damping_factor"});
      if (!ex.has("normal_restitution")) {
        // the restitution of the example's linear dashpot, head on and unclamped
        const double w0 = std::sqrt(ex.kn / ex.reduced_mass), gamma = ex.eta_n / (2 * ex.reduced_mass);
        const double en = std::exp(-gamma * std::numbers::pi / std::sqrt(w0 * w0 - gamma * gamma));
        e.added.push_back("contact.normal_restitution=" + number(en));
      }
    } else if (ex.has("normal_restitution")) {
      remove({"normal_restitution"});
      e.added.push_back("contact.normal_damping_rate=" + number(ex.eta_n / ex.reduced_mass));
    }
    if (!none && !c.mindlin() && !ex.has("tangential_stiffness"))
      e.added.push_back("contact.tangential_stiffness=" + number(ex.kt));
    damping_ratio = !none;
  }
  if (c.mindlin()) {
    remove({"tangential_stiffness", "tangential_stiffness_ratio", "tangential_restitution"});
    if (ex.has("tangential_restitution")) damping_ratio = true;
  }
  if (none) {
    remove({"friction", "tangential_stiffness", "tangential_stiffness_ratio", "tangential_restitution",
            "tangential_damping", "tangential_damping_rate", "tangential_damping_factor", "tangential_damping_ratio"});
    damping_ratio = false;
  }
  if (damping_ratio) {
    remove({"tangential_damping", "tangential_damping_rate", "tangential_damping_factor"});
    e.added.push_back("contact.tangential_damping_ratio=" + number(ex.eta_n > 0 ? ex.eta_t / ex.eta_n : 0.0));
  }
  if (c.rolling == "huet" && !ex.has("rolling_friction")) e.added.push_back("contact.rolling_friction=0.1");
  // [contact.wall] and [[contact.pair]] tables: the same keys go (they are commented out there too).
  return e;
}

// The Hertz and Mindlin keys a combination needs, by override.
std::vector<std::string> moduli_for(const Example& ex, const Combination& c) {
  std::vector<std::string> out;
  if (!c.hertz() && !c.mindlin()) return out;
  const std::string table = c.wall_only ? "contact.wall." : "contact.";
  out.push_back(table + "youngs_modulus=" + number(ex.youngs_modulus));
  out.push_back(table + "poisson_ratio=" + number(kPoisson));
  if (c.hertz()) out.push_back(table + "impact_speed=" + number(ex.impact_speed));
  return out;
}

Example read_example(const fs::path& path, const Variant& variant) {
  Example ex;
  ex.name = path.stem().string() + (variant.suffix.empty() ? "" : " " + variant.suffix);
  ex.display = "examples/" + path.filename().string();
  ex.text = read_text(path);
  ex.shrink = variant.shrink;
  io::ScenarioFile f = io::ScenarioFile::from_string(ex.text, ex.display);
  for (const auto& k : f.table_keys("contact")) ex.contact_keys.insert(k);
  ex.rule = read_tangential_model(f);
  for (const auto& o : ex.shrink) f.set_override(o);
  const Scenario sc = load_scenario(f);  // the example as shipped must load
  const World& w = *sc.world;
  const ParticleStore& p = w.particles();
  std::size_t first = 0;
  while (first < p.owned && p.is_fixed(first)) ++first;
  EXPECT_LT(first, p.owned) << ex.name << ": no mobile particle";
  if (first >= p.owned) return ex;
  for (std::size_t i = 0; i < p.owned; ++i) ex.shaped = ex.shaped || p.shape[i] != 0;
  const int s = p.species[first];
  const ContactParams& c = w.contacts().pair(s, s);
  ex.reduced_mass = 0.5 * p.mass[first];
  ex.reduced_radius = 0.5 * p.radius[first];
  ex.kn = c.normal_stiffness;
  ex.eta_n = c.normal_damping.at(ex.reduced_mass);
  ex.kt = c.tangential_stiffness;
  ex.eta_t = c.tangential_damping.at(ex.reduced_mass);
  if (f.has("contact.impact_speed")) ex.impact_speed = f.get<double>("contact.impact_speed");
  // The elastic Hertz impact as long as the linear one: E* from
  // 2.868 (m*^2 / (R* E*^2 v))^(1/5) = pi sqrt(m* / k_n), E = 2 (1 - nu^2) E*.
  const double t_linear = std::numbers::pi * std::sqrt(ex.reduced_mass / ex.kn);
  const double e_star =
      ex.reduced_mass / std::sqrt(ex.reduced_radius * ex.impact_speed) * std::pow(2.868 / t_linear, 2.5);
  ex.youngs_modulus = 2 * (1 - kPoisson * kPoisson) * e_star;
  // The contact-rich state: the example, linear as shipped but with a restitution of 0.1 so that
  // it settles, run until a quarter of its mobile bodies touch something, or kRichSteps steps.
  std::vector<std::string> settle = ex.shrink;
  if (ex.has("normal_restitution")) {
    settle.push_back("contact.normal_restitution=0.1");
  } else if (ex.has("normal_damping_rate")) {  // eta_n = 2 zeta sqrt(k_n m*), zeta = -ln e / sqrt(pi^2 + ln^2 e)
    const double ln_e = std::log(0.1), zeta = -ln_e / std::sqrt(std::numbers::pi * std::numbers::pi + ln_e * ln_e);
    settle.push_back("contact.normal_damping_rate=" + number(2 * zeta * std::sqrt(ex.kn / ex.reduced_mass)));
  }
  io::ScenarioFile g = io::ScenarioFile::from_string(ex.text, ex.display);
  for (const auto& o : settle) g.set_override(o);
  const Scenario settling = load_scenario(g);
  World& r = *settling.world;
  std::size_t mobile = 0;
  for (std::size_t i = 0; i < p.owned; ++i) mobile += !p.is_fixed(i);
  while (ex.rich_steps < kRichSteps && contacts_of(r) < (mobile + 3) / 4) {
    r.run(500);
    ex.rich_steps += 500;
  }
  ex.rich_contacts = contacts_of(r);
  ex.rich = state_of(r);
  return ex;
}

std::string first_line(const std::string& s) { return s.substr(0, s.find('\n')); }

TEST(ModelCombinations, EveryExampleRunsOrIsRefusedCleanly) {
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(fs::path(TALUS_SOURCE_DIR) / "examples"))
    if (entry.path().extension() == ".toml") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  ASSERT_FALSE(files.empty());
  const std::vector<Combination> combos = combinations();
  ASSERT_EQ(combos.size(), 72u);

  struct Tally {
    int set_ran = 0, set_refused = 0, edit_ran = 0, edit_refused = 0, hertz_ran = 0, mindlin_ran = 0;
    double max_travel = 0, max_overlap = 0, max_gain = -1e300;
    std::size_t min_contacts = SIZE_MAX, rich_contacts = 0;
    std::uint64_t rich_steps = 0;
    double seconds = 0;
  };
  std::vector<std::pair<std::string, Tally>> tallies;
  std::printf("%-18s %-40s %-13s %s\n", "example", "combination", "outcome", "first line of the message / edit");
  std::vector<std::pair<fs::path, Variant>> runs;
  for (const fs::path& path : files) {
    const auto it = kShrink.find(path.stem().string());
    for (const Variant& v : it != kShrink.end() ? it->second : std::vector<Variant>{Variant{}}) runs.emplace_back(path, v);
  }
  for (const auto& run : runs) {
    const fs::path& path = run.first;
    const Variant& variant = run.second;
    const auto te = std::chrono::steady_clock::now();
    const Example ex = read_example(path, variant);
    Tally t;
    for (const Combination& c : combos) {
      if (!variant.full_grid && !kRoughBase.contains(c.label)) continue;
      std::vector<std::string> overrides = ex.shrink;
      for (const auto& k : c.keys) overrides.push_back(k);
      for (const auto& k : moduli_for(ex, c)) overrides.push_back(k);
      auto check = [&](const Outcome& o, const char* how) {
        if (o.failed) ADD_FAILURE() << ex.display << variant.suffix << " [" << c.label << "] (" << how << "): " << o.message;
        if (!o.ran && !o.failed)
          EXPECT_TRUE(well_formed(o.message)) << ex.display << variant.suffix << " [" << c.label << "] (" << how
                                              << ") refused without FILE:LINE: KEY: message:\n" << o.message;
        if (o.ran) {
          t.max_travel = std::max(t.max_travel, o.max_travel);
          t.max_overlap = std::max(t.max_overlap, o.max_overlap);
          t.max_gain = std::max(t.max_gain, o.energy_gain);
          t.min_contacts = std::min(t.min_contacts, o.contacts);
        }
      };
      const Outcome plain = load_and_run(ex.text, ex.display, overrides, ex.rich);
      check(plain, "--set");
      bool ran = plain.ran;
      std::printf("%-18s %-40s %-13s %s\n", ex.name.c_str(), c.label.c_str(), plain.ran ? "ran --set" : "refused --set",
                  plain.ran ? "" : first_line(plain.message).c_str());
      plain.ran ? ++t.set_ran : ++t.set_refused;
      std::string refusal = plain.message;
      const Edit edit = edit_for(ex, c);
      const bool spheres_only = plain.message.find("needs spheres") != std::string::npos ||
                                plain.message.find("is for spheres") != std::string::npos;  // nothing to edit
      if (!plain.ran && !plain.failed && !spheres_only && (!edit.removed.empty() || !edit.added.empty())) {
        std::vector<std::string> edited_overrides = overrides;
        for (const auto& a : edit.added) edited_overrides.push_back(a);
        const Outcome edited =
            load_and_run(without_contact_keys(ex.text, edit.removed), ex.display, edited_overrides, ex.rich);
        check(edited, "edited");
        ran = edited.ran;
        refusal = edited.message;
        std::printf("%-18s %-40s %-13s %s%s%s\n", "", "", edited.ran ? "ran edit" : "refused edit",
                    edit.summary().c_str(), edited.ran ? "" : " => ", edited.ran ? "" : first_line(edited.message).c_str());
        edited.ran ? ++t.edit_ran : ++t.edit_refused;
      }
      if (ran && c.main && c.hertz()) ++t.hertz_ran;
      if (ran && c.main && c.mindlin()) ++t.mindlin_ran;

      // What must run and what must be refused.
      if (c.main) {
        const bool sphere_only = c.hertz() || c.mindlin() || c.rolling == "huet";
        if (!ex.shaped || !sphere_only) {
          EXPECT_TRUE(ran) << ex.display << variant.suffix << " [" << c.label << "] should run:\n" << refusal;
        } else {
          EXPECT_FALSE(ran) << ex.display << variant.suffix << " [" << c.label << "] should be refused (shaped bodies)";
          EXPECT_TRUE(refusal.find("for spheres") != std::string::npos || refusal.find("needs spheres") != std::string::npos)
              << ex.display << variant.suffix << " [" << c.label << "]: " << refusal;
        }
      } else if (c.label.starts_with("model=")) {
        EXPECT_TRUE(plain.ran) << ex.display << variant.suffix << " [" << c.label << "] should run:\n" << plain.message;
      } else if (c.wall_only && !c.tangential.empty() && c.tangential != "none") {
        // One history rule per run: a wall table may not change it (a shaped body refuses Hertz first).
        const std::string rule = c.tangential == "mindlin" ? "elastic_spring" : c.tangential;
        const std::string run_rule = ex.rule == TangentialModel::elastic_spring ? "elastic_spring"
                                     : ex.rule == TangentialModel::memoryless   ? "memoryless"
                                                                                : "memory";
        const bool shaped_refusal = ex.shaped && spheres_only;
        if (rule != run_rule && !shaped_refusal)
          EXPECT_NE(plain.message.find("one history rule per run"), std::string::npos)
              << ex.display << variant.suffix << " [" << c.label << "]: " << plain.message;
      }
    }
    t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - te).count();
    EXPECT_GT(t.set_ran, 0) << ex.display << " refuses every combination";
    if (!ex.shaped && variant.full_grid) {
      EXPECT_GT(t.hertz_ran, 0) << ex.display << ": no Hertz combination ran";
      EXPECT_GT(t.mindlin_ran, 0) << ex.display << ": no Mindlin combination ran";
    }
    t.rich_steps = ex.rich_steps;
    t.rich_contacts = ex.rich_contacts;
    tallies.emplace_back(ex.name, t);
  }
  std::printf("\n%-18s %7s %11s %8s %12s %5s %7s %15s %8s %7s %8s %8s %7s\n", "example", "ran:set", "refused:set",
              "ran:edit", "refused:edit", "hertz", "mindlin", "rich: steps/ctc", "min ctc", "travel", "overlap", "dE/E",
              "seconds");
  for (const auto& [name, t] : tallies)
    std::printf("%-18s %7d %11d %8d %12d %5d %7d %9llu/%-5zu %8zu %7.2g %8.2g %8.1e %7.1f\n", name.c_str(), t.set_ran,
                t.set_refused, t.edit_ran, t.edit_refused, t.hertz_ran, t.mindlin_ran,
                static_cast<unsigned long long>(t.rich_steps), t.rich_contacts, t.min_contacts, t.max_travel,
                t.max_overlap, t.max_gain, t.seconds);
  std::printf("%zu examples (%zu rows) x up to %zu combinations in %.1f s\n", files.size(), runs.size(), combos.size(),
              std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
}


// settling_box.toml says "try --set contact.model=memoryless": the memoryless model reads the
// spring models' tangential keys (Pournin's eta_t is its viscous friction) instead of calling
// them unknown, as the first reader of the sub-models did.
TEST(ModelCombinations, MemorylessTakesTheSpringModelsKeys) {
  for (const char* name : {"settling_box", "hopper", "chute"}) {
    io::ScenarioFile f =
        io::ScenarioFile::from_string(read_text(fs::path(TALUS_SOURCE_DIR) / "examples" / (std::string(name) + ".toml")), name);
    for (const auto& o : kShrink.contains(name) ? kShrink.at(name).front().shrink : std::vector<std::string>{})
      f.set_override(o);
    f.set_override("contact.model=memoryless");
    Scenario sc;
    ASSERT_NO_THROW(sc = load_scenario(f)) << name;
    const ContactParams& c = sc.world->contacts().pair(0, 0);
    EXPECT_GT(c.tangential_damping.at(1e-6) + c.tangential_damping.at(1.0), 0) << name << ": no viscous friction";
  }
}

// A sphere dropped at 1 m/s on a floor, under heavy damping: the time step resolves the impact
// (not the slow end of an unclamped, heavily damped one), so nothing leaves faster than it came.
// These used to stop `talus check` with "overdamped contact: no collision time" (a clamped linear
// contact with e_n < exp(-2)), or pass it and then shoot the sphere off at 27 m/s (linear,
// unclamped, zeta = 0.9999) or 1351 m/s (Hertz, viscous, unclamped).
TEST(ModelCombinations, HeavyDampingKeepsTheStepStable) {
  const std::string drop = R"([run]
end_time = 0.01

[domain]
lo = [-0.1, -0.1, 0.0]
hi = [0.1, 0.1, 0.2]

[species.glass]
density = 2500
radius = 0.001

[[particles]]
species = "glass"
position = [0.0, 0.0, 0.00105]
velocity = [0.0, 0.0, -1.0]

[[walls]]
name = "floor"
point = [0.0, 0.0, 0.0]
normal = [0.0, 0.0, 1.0]

[contact]
friction = 0.5
)";
  // m = 1.047e-5 kg: against the wall the critical dashpot of k_n = 2e4 is a rate of 8.74e4 /s.
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"linear, clamped, e = 0.1", "normal_stiffness = 2e4\nnormal_restitution = 0.1\n"},
      {"linear, clamped, e = 0.01", "normal_stiffness = 2e4\nnormal_restitution = 0.01\n"},
      {"linear, unclamped, zeta = 0.9999", "model = \"elastic_spring\"\nnormal_stiffness = 2e4\nnormal_damping_rate = 8.7394e4\n"},
      // Unclamped past critical damping (zeta = 2) is refused: the pair never separates.
      {"hertz, viscous, unclamped", "normal = \"hertz\"\nyoungs_modulus = 1e8\npoisson_ratio = 0.3\nimpact_speed = 1.0\n"
                                    "damping = \"viscous\"\nnormal_clamp = false\nnormal_damping_rate = 1e5\n"},
      {"hertz, tsuji, unclamped, e = 1e-5", "normal = \"hertz\"\nyoungs_modulus = 1e8\npoisson_ratio = 0.3\nimpact_speed = 1.0\n"
                                           "normal_clamp = false\nnormal_restitution = 1e-5\n"},
      {"hertz, tsuji, clamped, e = 1e-5", "normal = \"hertz\"\nyoungs_modulus = 1e8\npoisson_ratio = 0.3\nimpact_speed = 1.0\n"
                                         "normal_restitution = 1e-5\n"},
  };
  for (const auto& [label, contact] : cases) {
    Scenario sc;
    try {
      io::ScenarioFile f = io::ScenarioFile::from_string(drop + contact, "drop.toml");
      sc = load_scenario(f);
    } catch (const std::exception& e) {
      ADD_FAILURE() << label << ": " << e.what();
      continue;
    }
    World& w = *sc.world;
    const double dt = w.settings().time_step;
    EXPECT_LT(dt, 1e-5) << label;
    double fastest = 0, rebound = 0;
    bool touched = false;
    for (int k = 0; k < 4000 && w.time() < 0.004; ++k) {
      w.step();
      const Diagnostics d = w.diagnostics();
      touched = touched || d.wall_contacts > 0;
      fastest = std::max(fastest, d.max_speed);
      rebound = std::max(rebound, w.particles().velocity[0].z);
    }
    EXPECT_TRUE(touched) << label;
    EXPECT_TRUE(std::isfinite(fastest)) << label;
    EXPECT_LT(fastest, 1.05) << label << ": dt = " << dt;  // 1 m/s and 4 ms of gravity
    EXPECT_LT(rebound, 0.15) << label << ": dt = " << dt;  // e_n <= 0.1 (0 for the creeping ones)
  }
}

// A chute on a flat base (base_diameter = 0, a wall) starts with every flowing sphere clear of
// the wall; they used to be placed from z = 0, up to a radius deep in it, and were shot off.
TEST(ModelCombinations, FlatBaseChuteStartsClearOfTheBase) {
  ChuteSetup s;
  s.flow = s.base = weinhart_chute_contact();
  s.base_diameter = 0;
  s.fill_height = 2;
  s.length = 10;
  s.width = 5;
  auto w = build_chute(s);
  const ParticleStore& p = w->particles();
  ASSERT_GT(p.owned, 0u);
  for (std::size_t i = 0; i < p.owned; ++i) EXPECT_GE(p.position[i].z, p.radius[i]) << "particle " << i;
  w->run(200);
  EXPECT_LT(w->diagnostics().max_speed, 1.0);
}

TEST(ModelCombinations, ChuteLayerStartsAtItsInitialVolumeFraction) {
  // Weinhart et al. 2012, Sect. 5: the layer is placed at about 0.3 and falls to about H.
  ChuteSetup s;
  s.flow = s.base = weinhart_chute_contact();
  s.fill_height = 6;
  s.length = 10;
  s.width = 5;
  auto w = build_chute(s);
  const ParticleStore& p = w->particles();
  const double volume = std::numbers::pi / 6;
  const double top = 6 * 50 * volume / (50 * s.initial_volume_fraction);  // 10.47
  std::size_t flowing = 0, in_slab = 0;
  double highest = 0;
  for (std::size_t i = 0; i < p.owned; ++i) {
    if (p.species[i] != 0) continue;
    ++flowing;
    highest = std::max(highest, p.position[i].z);
    if (p.position[i].z > 1 && p.position[i].z < top - 1) ++in_slab;
  }
  EXPECT_EQ(flowing, 300u);
  EXPECT_LE(highest, top);
  EXPECT_GT(highest, top - 1);
  // About 240 centres in the slab: a binomial standard deviation of 2.8 %, so 10 % is 3.5 sigma.
  const double fraction = static_cast<double>(in_slab) * volume / (50 * (top - 2));
  EXPECT_NEAR(fraction, 0.3, 0.03);
}

}  // namespace
}  // namespace talus
