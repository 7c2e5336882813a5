#include "talus/io/snapshot_json.h"

namespace talus {

namespace {

std::vector<double> flat(const Vec3& v) { return {v.x, v.y, v.z}; }
Vec3 vec(const nlohmann::json& j) { return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()}; }

}  // namespace

nlohmann::json snapshot_to_json(const Snapshot& s) {
  nlohmann::json particles = nlohmann::json::array();
  for (const ParticleRecord& p : s.particles)
    particles.push_back({p.id, p.species, p.shape, p.fixed, p.mass, p.radius, p.volume, flat(p.position),
                         flat(p.velocity), flat(p.angular_velocity),
                         std::vector<double>{p.orientation.w, p.orientation.x, p.orientation.y, p.orientation.z}});
  return {{"time", s.time},
          {"gravity", flat(s.gravity)},
          {"domain_min", flat(s.domain_min)},
          {"domain_max", flat(s.domain_max)},
          {"periodic", std::vector<bool>{s.periodic[0], s.periodic[1], s.periodic[2]}},
          {"particles", particles}};
}

Snapshot snapshot_from_json(const nlohmann::json& j) {
  Snapshot s;
  s.time = j.at("time").get<double>();
  s.gravity = vec(j.at("gravity"));
  s.domain_min = vec(j.at("domain_min"));
  s.domain_max = vec(j.at("domain_max"));
  for (int a = 0; a < 3; ++a) s.periodic[a] = j.at("periodic").at(a).get<bool>();
  for (const nlohmann::json& r : j.at("particles")) {
    ParticleRecord p;
    p.id = r.at(0).get<std::uint32_t>();
    p.species = r.at(1).get<int>();
    p.shape = r.at(2).get<int>();
    p.fixed = r.at(3).get<bool>();
    p.mass = r.at(4).get<double>();
    p.radius = r.at(5).get<double>();
    p.volume = r.at(6).get<double>();
    p.position = vec(r.at(7));
    p.velocity = vec(r.at(8));
    p.angular_velocity = vec(r.at(9));
    const nlohmann::json& q = r.at(10);
    p.orientation = Quat{q.at(0).get<double>(), q.at(1).get<double>(), q.at(2).get<double>(), q.at(3).get<double>()};
    s.particles.push_back(p);
  }
  return s;
}

}  // namespace talus
