#include "talus/scenario/contact_reader.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "talus/contact/head_on_impact.h"
#include "talus/contact/parameter_procedure.h"

namespace talus {

namespace {

class ChainReader {
 public:
  ChainReader(const io::ScenarioFile& f, const std::vector<std::string>& tables) : f_(f), tables_(tables) {}
  // Full key of the first table holding `name`, or nothing.
  std::optional<std::string> where(const std::string& name) const {
    for (const auto& t : tables_)
      if (f_.has(t + "." + name)) return t + "." + name;
    return std::nullopt;
  }
  std::optional<double> number(const std::string& name, io::Check check = {}) const {
    if (auto key = where(name)) return f_.get<double>(*key, check);
    return std::nullopt;
  }
  std::optional<std::string> choice(const std::string& name, const std::vector<std::string>& allowed) const {
    if (auto key = where(name)) return f_.get_choice(*key, allowed);
    return std::nullopt;
  }
  // At most one of `names` may be given; returns the index given, or -1.
  int which_of(const std::vector<std::string>& names) const {
    int found = -1;
    for (std::size_t k = 0; k < names.size(); ++k) {
      if (!where(names[k])) continue;
      if (found >= 0)
        f_.fail(*where(names[k]), "give only one of " + names[found] + " and " + names[k]);
      found = static_cast<int>(k);
    }
    return found;
  }
  // Refuses `name` with `why` if the contact's own (first) table gives it.
  void refuse(const std::string& name, const std::string& why) const {
    const std::string key = tables_.front() + "." + name;
    if (f_.has(key)) f_.fail(key, why);
  }
  // Explains `name`, wherever given, if nothing reads it: a known key the chosen models ignore.
  void unused(const std::string& name, const std::string& why) const {
    for (const auto& t : tables_)
      if (f_.has(t + "." + name)) f_.explain_if_unread(t + "." + name, why);
  }
  // The key of `name` for messages: where it is given, else in the contact's own table.
  std::string key_of(const std::string& name) const { return where(name).value_or(tables_.front() + "." + name); }
  const io::ScenarioFile& file() const { return f_; }
  std::string primary() const { return tables_.front(); }

 private:
  const io::ScenarioFile& f_;
  std::vector<std::string> tables_;
};

// The tangential sub-models: name, history rule, stiffness law.
struct TangentialChoice {
  const char* name;
  TangentialModel rule;
  TangentialStiffness stiffness;
};
constexpr TangentialChoice kTangential[] = {
    {"memory", TangentialModel::memory, TangentialStiffness::constant},                  // Huet et al. 2021, Eqs. 6-8
    {"elastic_spring", TangentialModel::elastic_spring, TangentialStiffness::constant},  // Weinhart et al. 2012, Eqs. 7-9
    {"mindlin", TangentialModel::elastic_spring, TangentialStiffness::mindlin},          // Mindlin 1949, k_t = 8 G* a
    {"memoryless", TangentialModel::memoryless, TangentialStiffness::constant},          // Huet et al. 2021, Sect. V B
    {"none", TangentialModel::memoryless, TangentialStiffness::constant},                // frictionless
};
std::vector<std::string> tangential_names() {
  std::vector<std::string> names;
  for (const auto& t : kTangential) names.push_back(t.name);
  return names;
}
const TangentialChoice& tangential_named(const std::string& name) {
  for (const auto& t : kTangential)
    if (name == t.name) return t;
  return kTangential[0];
}

// The shorthand contact.model names a history rule and the clamp that goes with it.
std::string model_shorthand(const io::ScenarioFile& f) {
  return f.get_choice_or("contact.model", "memory", {"memory", "memoryless", "elastic_spring"});
}

// eta = -2 ln(e) sqrt(k_n m_ij) / sqrt(pi^2 + ln^2 e) (Huet et al. 2021, Eq. 17), as a law in sqrt(m_ij).
DampingLaw damping_from_restitution_eq17(double kn, double e) {
  DampingLaw d;
  if (e >= 1) return d;
  const double ln_e = std::log(e);
  d.per_sqrt_reduced_mass = -2 * ln_e * std::sqrt(kn) / std::sqrt(std::numbers::pi * std::numbers::pi + ln_e * ln_e);
  return d;
}

// The normal dashpot that makes the measured restitution e: solved with the clamp and the law
// (head_on_impact.h), or Eq. (17) of Huet et al. 2021 literally when `restitution_damping` is
// "eq11" (the value names Eq. (11), the unclamped spring-dashpot's restitution that Eq. (17)
// inverts; it ignores the clamp, so a clamped contact then rebounds faster than e).
DampingLaw damping_for_restitution(const ChainReader& r, const ContactParams& c, double e, bool clamp) {
  const std::string formula = r.choice("restitution_damping", {"solved", "eq11"}).value_or("solved");
  if (formula == "eq11") {
    if (c.normal_law != normal_law_index<LinearNormal>())
      r.file().fail(r.key_of("restitution_damping"), "\"eq11\" is the linear spring's formula (Huet et al. 2021, Eqs. 11 and 17)");
    return damping_from_restitution_eq17(c.normal_stiffness, e);
  }
  if (e >= 1) return {};
  if (!clamp && c.normal_law == normal_law_index<LinearNormal>()) return damping_from_restitution_eq17(c.normal_stiffness, e);
  DampingLaw d;
  d.per_sqrt_reduced_mass = params::damping_for_restitution(c.normal_law, clamp, e) * std::sqrt(c.normal_stiffness);
  return d;
}

DampingLaw read_damping(const ChainReader& r, const std::string& prefix, const ContactParams& c, bool clamp) {
  const std::vector<std::string> names = {prefix + "_damping", prefix + "_damping_rate", prefix + "_damping_factor",
                                          prefix + "_restitution"};
  DampingLaw d;
  const int given = r.which_of(names);
  if (prefix == "normal" && given >= 0 && given != 3)
    r.unused("restitution_damping", "it says how normal_restitution becomes a dashpot, and this contact gives " +
                                        names[given] + " instead");
  if (c.damping_scaling == DampingScaling::tsuji && given >= 0 && given != 3)
    r.file().fail(*r.where(names[given]), "damping = \"tsuji\" takes " + prefix +
                                              "_restitution (its dashpot grows with the contact; Tsuji et al. 1992)");
  switch (given) {
    case 0: d.coefficient = *r.number(names[0], io::non_negative); break;       // N s/m
    case 1: d.per_reduced_mass = *r.number(names[1], io::non_negative); break;  // Silbert: eta = gamma m_ij
    case 2: d.per_reduced_mass = 2 * *r.number(names[2], io::non_negative); break;  // Huet: gamma = eta / (2 m_ij)
    case 3: {
      const double e = *r.number(names[3], io::in_range(1e-6, 1));
      if (c.normal_stiffness <= 0) r.file().fail(*r.where(names[3]), "needs a positive stiffness");
      if (c.normal_law != normal_law_index<LinearNormal>() && c.damping_scaling != DampingScaling::tsuji)
        r.file().fail(*r.where(names[3]), "with a constant dashpot a Hertz contact's restitution depends on the impact "
                                          "speed: use damping = \"tsuji\"");
      d = damping_for_restitution(r, c, e, clamp);
      break;
    }
    default: break;
  }
  return d;
}

// Hertz and Mindlin: the effective moduli from contact.youngs_modulus and poisson_ratio.
ElasticModuli read_moduli(const ChainReader& r, const ContactContext& ctx, const std::string& needed_by) {
  const auto e = r.where("youngs_modulus");
  if (!e) r.file().fail(r.key_of("youngs_modulus"), "missing: " + needed_by + " needs youngs_modulus (Pa) and poisson_ratio");
  const auto nu = r.where("poisson_ratio");
  if (!nu) r.file().fail(r.key_of("poisson_ratio"), "missing: " + needed_by + " needs youngs_modulus (Pa) and poisson_ratio");
  return elastic_moduli(r.file().get<double>(*e, io::positive), r.file().get<double>(*nu, io::in_range(-0.999, 0.5)),
                        ctx.wall);
}

void read_normal(const ChainReader& r, const ContactContext& ctx, ContactParams& c) {
  const io::ScenarioFile& f = r.file();
  const std::vector<std::string> laws = NormalLaws::names();
  const std::string law = r.choice("normal", laws).value_or(laws.front());
  for (std::size_t k = 0; k < laws.size(); ++k)
    if (laws[k] == law) c.normal_law = static_cast<std::uint8_t>(k);
  const bool linear = c.normal_law == normal_law_index<LinearNormal>();
  if (!linear && ctx.shaped)
    f.fail(r.key_of("normal"), "\"" + law + "\" needs spheres: a shaped body has no single radius of curvature");
  c.damping_scaling = r.choice("damping", {"viscous", "tsuji"}).value_or(linear ? "viscous" : "tsuji") == "tsuji"
                          ? DampingScaling::tsuji
                          : DampingScaling::constant;
  if (linear) {
    c.damping_scaling = DampingScaling::constant;  // a linear spring's stiffness does not grow: the same dashpot
    // Normal stiffness: given, or from the largest overlap at an impact speed (Huet et al. 2021, Eq. 16).
    switch (r.which_of({"normal_stiffness", "max_overlap"})) {
      case 0: c.normal_stiffness = *r.number("normal_stiffness", io::positive); break;
      case 1: {
        const double overlap = *r.number("max_overlap", io::positive);
        const auto speed_key = r.where("impact_speed");
        if (!speed_key) f.fail(*r.where("max_overlap"), "needs impact_speed (m/s) beside it (Huet et al. 2021, Eq. 16)");
        const double speed = f.get<double>(*speed_key, io::positive);
        const auto e_key = r.where("normal_restitution");
        if (!e_key) f.fail(*r.where("max_overlap"), "needs normal_restitution beside it (Huet et al. 2021, Eq. 16)");
        const double e = f.get<double>(*e_key, io::in_range(1e-6, 0.999999));
        c.normal_stiffness = params::normal_stiffness_for_overlap(ctx.reduced_mass, speed, overlap, e);
        break;
      }
      default: f.fail(r.primary(), "missing normal_stiffness (N/m), or max_overlap with impact_speed");
    }
    r.unused("impact_speed", "a linear spring reads it only beside max_overlap; normal = \"hertz\" reads it for its contact time");
    for (const char* k : {"youngs_modulus", "poisson_ratio"})
      r.unused(k, "read by normal = \"hertz\" and tangential = \"mindlin\" only");
    return;
  }
  r.refuse("normal_stiffness", "normal = \"" + law + "\" takes youngs_modulus and poisson_ratio");
  r.refuse("max_overlap", "normal = \"" + law + "\" takes youngs_modulus and poisson_ratio");
  c.normal_stiffness = hertz_stiffness(read_moduli(r, ctx, "normal = \"" + law + "\""));
  const auto speed = r.where("impact_speed");
  if (!speed)
    f.fail(r.key_of("impact_speed"), "missing: normal = \"" + law +
                                         "\" needs the fastest expected impact speed (m/s), which sets its contact time");
  c.impact_speed = f.get<double>(*speed, io::positive);
}

void read_tangential(const ChainReader& r, const ContactContext& ctx, ContactParams& c, const std::string& name) {
  const io::ScenarioFile& f = r.file();
  const bool linear = c.normal_law == normal_law_index<LinearNormal>();
  if (name == "mindlin") {
    if (ctx.shaped) f.fail(r.key_of("tangential"), "\"mindlin\" needs spheres: a shaped body has no single radius of curvature");
    for (const char* k : {"tangential_stiffness", "tangential_stiffness_ratio", "tangential_restitution"})
      r.refuse(k, "tangential = \"mindlin\" takes its stiffness from youngs_modulus and poisson_ratio");
    c.tangential_law = TangentialStiffness::mindlin;
    c.tangential_stiffness = mindlin_stiffness(read_moduli(r, ctx, "tangential = \"mindlin\""));
  } else if (name == "none") {
    // no spring
  } else {
    // Tangential stiffness: given, as a ratio to k_n, or after Pournin (Huet et al. 2021, Eqs. 18-19).
    // "memoryless" keeps no spring but reads them too: Pournin's eta_t is its viscous friction, and
    // a file written for the spring models runs memoryless with --set contact.model=memoryless
    // (Huet et al. 2021, Sect. V B compares both on one packing).
    switch (r.which_of({"tangential_stiffness", "tangential_stiffness_ratio", "tangential_restitution"})) {
      case 0: c.tangential_stiffness = *r.number("tangential_stiffness", io::non_negative); break;
      case 1:
        if (!linear) f.fail(r.key_of("tangential_stiffness_ratio"), "a ratio to k_n needs normal = \"linear\" (or use tangential = \"mindlin\")");
        c.tangential_stiffness = *r.number("tangential_stiffness_ratio", io::non_negative) * c.normal_stiffness;
        break;
      case 2: {
        if (!linear) f.fail(r.key_of("tangential_restitution"), "Eqs. (18)-(19) need normal = \"linear\"");
        const double et = *r.number("tangential_restitution", io::in_range(1e-6, 0.999999));
        const auto e_key = r.where("normal_restitution");
        if (!e_key) f.fail(*r.where("tangential_restitution"), "needs normal_restitution beside it (Eqs. 18-19)");
        const double en = f.get<double>(*e_key);
        const double eta_n = c.normal_damping.at(ctx.reduced_mass);
        const auto t = params::pournin_tangential(c.normal_stiffness, eta_n, ctx.reduced_mass, ctx.radius_i, ctx.inertia_i,
                                                  ctx.radius_j, ctx.inertia_j, en, et);
        c.tangential_stiffness = t.stiffness;
        c.tangential_damping.coefficient = t.damping;
        break;
      }
      default: break;
    }
  }
  const int damping = r.which_of({"tangential_damping", "tangential_damping_rate", "tangential_damping_factor",
                                  "tangential_damping_ratio"});
  if (damping == 3) {  // eta_t = ratio eta_n, whatever the normal dashpot's convention
    const double ratio = *r.number("tangential_damping_ratio", io::non_negative);
    const DampingLaw& n = c.normal_damping;
    c.tangential_damping = {ratio * n.coefficient, ratio * n.per_reduced_mass, ratio * n.per_sqrt_reduced_mass};
  } else if (damping >= 0) {
    if (c.damping_scaling == DampingScaling::tsuji)
      f.fail(*r.where(std::vector<std::string>{"tangential_damping", "tangential_damping_rate", "tangential_damping_factor"}[damping]),
             "with damping = \"tsuji\" give tangential_damping_ratio (eta_t / eta_n)");
    ContactParams viscous = c;
    viscous.damping_scaling = DampingScaling::constant;
    c.tangential_damping = read_damping(r, "tangential", viscous, false);
  }
  c.friction = r.number("friction", io::non_negative).value_or(0.0);
  if (name == "none") {
    for (const char* k : {"friction", "tangential_damping", "tangential_damping_rate", "tangential_damping_factor",
                          "tangential_damping_ratio"})
      r.refuse(k, "tangential = \"none\" is frictionless");
    c.friction = 0;
    c.tangential_stiffness = 0;
    c.tangential_damping = {};
  }
}

void read_rolling(const ChainReader& r, const ContactContext& ctx, ContactParams& c) {
  const auto mu_r = r.number("rolling_friction", io::non_negative);
  const std::string model = r.choice("rolling", {"huet", "none"}).value_or(mu_r && *mu_r > 0 ? "huet" : "none");
  if (model == "none") {
    r.refuse("rolling_stiffness", "rolling = \"none\"");
    r.refuse("rolling_damping", "rolling = \"none\"");
    return;
  }
  // Huet et al. 2021, App. A: a rolling spring-dashpot-slider for spheres standing in for shape.
  if (!mu_r || *mu_r <= 0) r.file().fail(r.key_of("rolling_friction"), "rolling = \"huet\" needs a positive rolling_friction");
  if (ctx.shaped)
    r.file().fail(r.key_of("rolling_friction"),
                  "rolling resistance (Huet et al. 2021, App. A) is for spheres; a shaped body resists rolling by its shape");
  if (ctx.model == TangentialModel::memoryless && r.where("rolling_stiffness"))
    r.file().fail(*r.where("rolling_stiffness"), "the memoryless model has no rolling spring (viscous rolling only)");
  c.rolling.enabled = true;
  c.rolling.friction = *mu_r;
  if (r.which_of({"rolling_stiffness"}) == 0) {
    c.rolling.from_normal = false;
    c.rolling.stiffness = *r.number("rolling_stiffness", io::non_negative);
    c.rolling.damping = r.number("rolling_damping", io::non_negative).value_or(0.0);
  } else {
    r.refuse("rolling_damping", "needs rolling_stiffness beside it (otherwise both follow k_n, Eq. A9)");
  }
}

}  // namespace

TangentialModel read_tangential_model(const io::ScenarioFile& f) {
  return tangential_named(f.get_choice_or("contact.tangential", model_shorthand(f), tangential_names())).rule;
}

ContactParams read_contact(const io::ScenarioFile& f, const std::vector<std::string>& tables, const ContactContext& ctx) {
  const ChainReader r(f, tables);
  ContactParams c;
  read_normal(r, ctx, c);

  const std::string shorthand = model_shorthand(f);
  const std::string tangential = r.choice("tangential", tangential_names()).value_or(shorthand);
  const TangentialChoice& t = tangential_named(tangential);
  if (tangential != "none" && t.rule != ctx.model)
    f.fail(r.key_of("tangential"), "\"" + tangential + "\" keeps the " + tangential_model_name(t.rule) +
                                       " history, but this run's contacts keep the " + tangential_model_name(ctx.model) +
                                       " history (contact.tangential): one history rule per run");
  // Huet et al. 2021, Eq. (5) bounds the force at zero; Weinhart et al. 2012, Eq. (3) does not.
  const auto clamp_key = r.where("normal_clamp");
  const bool clamp = clamp_key ? f.get<bool>(*clamp_key) : ctx.model != TangentialModel::elastic_spring;
  c.clamp = clamp ? NormalClamp::clamped : NormalClamp::free;
  c.normal_damping = read_damping(r, "normal", c, clamp);
  // Past critical damping an unclamped linear contact never separates (the overlap creeps back to
  // zero): it has no contact time (Weinhart et al. 2012, Eq. 5) to take the time step from.
  if (!clamp && c.normal_law == normal_law_index<LinearNormal>()) {
    const double zeta = c.normal_damping.at(ctx.reduced_mass) / (2 * std::sqrt(c.normal_stiffness * ctx.reduced_mass));
    if (zeta >= 1) {
      std::string key = r.key_of("normal_damping");
      for (const char* name : {"normal_damping_rate", "normal_damping_factor"})
        if (auto given = r.where(name)) key = *given;
      f.fail(key, "overdamped (zeta = " + std::to_string(zeta) +
                      "): without the clamp the pair never separates; lower the damping or set normal_clamp = true");
    }
  }
  read_tangential(r, ctx, c, tangential);
  read_rolling(r, ctx, c);
  return c;
}

double contact_duration(const ContactParams& c, double reduced_mass, double reduced_radius) {
  if (c.normal_law == normal_law_index<LinearNormal>()) {
    const double eta = c.normal_damping.at(reduced_mass);
    // Near critical damping Eq. (5) grows without bound while the dashpot's own time scale
    // 2 pi m / eta shrinks: the step follows the shorter, and never exceeds the one of twice the
    // undamped half period (for zeta <= 0.5, every shipped example, Eq. 5 is the shortest; up to 0.707 it is).
    const double half_period = std::numbers::pi * std::sqrt(reduced_mass / c.normal_stiffness);
    if (eta < 2 * std::sqrt(c.normal_stiffness * reduced_mass))
      return std::min({params::collision_time(c.normal_stiffness, eta, reduced_mass), 2 * half_period,
                       eta > 0 ? 2 * std::numbers::pi * reduced_mass / eta : 2 * half_period});
    // Past critical damping (a clamped contact solved for e_n < exp(-2), or a dashpot given) the
    // time scale is the dashpot's, 2 pi m / eta (an explicit step must stay below 2 m / eta), or
    // the undamped half period if shorter.
    return std::min(half_period, 2 * std::numbers::pi * reduced_mass / eta);
  }
  // The damped impact at impact_speed; a dashpot so strong that the pair creeps apart would give
  // no time scale, so the elastic impact (the shorter) bounds it.
  ContactParams elastic = c;
  elastic.normal_damping = {};
  const double undamped = params::head_on_impact(elastic, reduced_mass, reduced_radius, c.impact_speed, true).duration;
  const double damped = params::head_on_impact(c, reduced_mass, reduced_radius, c.impact_speed, c.clamp != NormalClamp::free).duration;
  return std::min(damped, undamped);
}

}  // namespace talus
