#include "talus/scenario/contact_reader.h"

#include <cmath>
#include <numbers>
#include <optional>

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
  const io::ScenarioFile& file() const { return f_; }
  std::string primary() const { return tables_.front(); }

 private:
  const io::ScenarioFile& f_;
  std::vector<std::string> tables_;
};

// eta = -2 ln(e) sqrt(k_n m_ij) / sqrt(pi^2 + ln^2 e) (Huet et al. 2021, Eq. 17), as a law in sqrt(m_ij).
DampingLaw damping_from_restitution(double kn, double e) {
  DampingLaw d;
  if (e >= 1) return d;
  const double ln_e = std::log(e);
  d.per_sqrt_reduced_mass = -2 * ln_e * std::sqrt(kn) / std::sqrt(std::numbers::pi * std::numbers::pi + ln_e * ln_e);
  return d;
}

DampingLaw read_damping(const ChainReader& r, const std::string& prefix, double kn) {
  const std::vector<std::string> names = {prefix + "_damping", prefix + "_damping_rate", prefix + "_damping_factor",
                                          prefix + "_restitution"};
  DampingLaw d;
  switch (r.which_of(names)) {
    case 0: d.coefficient = *r.number(names[0], io::non_negative); break;       // N s/m
    case 1: d.per_reduced_mass = *r.number(names[1], io::non_negative); break;  // Silbert: eta = gamma m_ij
    case 2: d.per_reduced_mass = 2 * *r.number(names[2], io::non_negative); break;  // Huet: gamma = eta / (2 m_ij)
    case 3: {
      const double e = *r.number(names[3], io::in_range(1e-6, 1));
      if (kn <= 0) r.file().fail(*r.where(names[3]), "needs a positive stiffness");
      d = damping_from_restitution(kn, e);
      break;
    }
    default: break;
  }
  return d;
}

}  // namespace

ContactParams read_contact(const io::ScenarioFile& f, const std::vector<std::string>& tables, const ContactContext& ctx) {
  const ChainReader r(f, tables);
  ContactParams c;
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
  c.normal_damping = read_damping(r, "normal", c.normal_stiffness);

  // Tangential stiffness: given, as a ratio to k_n, or after Pournin (Huet et al. 2021, Eqs. 18-19).
  switch (r.which_of({"tangential_stiffness", "tangential_stiffness_ratio", "tangential_restitution"})) {
    case 0: c.tangential_stiffness = *r.number("tangential_stiffness", io::non_negative); break;
    case 1: c.tangential_stiffness = *r.number("tangential_stiffness_ratio", io::non_negative) * c.normal_stiffness; break;
    case 2: {
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
  if (r.which_of({"tangential_damping", "tangential_damping_rate", "tangential_damping_factor"}) >= 0)
    c.tangential_damping = read_damping(r, "tangential", c.tangential_stiffness);
  c.friction = r.number("friction", io::non_negative).value_or(0.0);

  if (auto mu_r = r.number("rolling_friction", io::non_negative)) {
    c.rolling.enabled = *mu_r > 0;
    c.rolling.friction = *mu_r;
    const int given = r.which_of({"rolling_stiffness"});
    if (given == 0) {
      c.rolling.from_normal = false;
      c.rolling.stiffness = *r.number("rolling_stiffness", io::non_negative);
      c.rolling.damping = r.number("rolling_damping", io::non_negative).value_or(0.0);
    }
  }
  return c;
}

}  // namespace talus
