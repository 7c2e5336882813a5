#include "talus/io/checkpoint_file.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <stdexcept>

#include "talus/io/atomic_file.h"
#include "talus/io/flat_arrays.h"
#include "talus/io/hdf5_file.h"
#include "talus/io/input_error.h"
#include "talus/io/json_file.h"

namespace talus::io {

namespace {

constexpr const char* kFormat = "talus-checkpoint";

// ---- walls as JSON (doubles round-trip exactly through nlohmann's shortest form) ----

nlohmann::json vec_json(const Vec3& v) { return {v.x, v.y, v.z}; }
Vec3 json_vec(const nlohmann::json& j) { return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()}; }

nlohmann::json walls_json(const std::vector<Wall>& walls) {
  nlohmann::json out = nlohmann::json::array();
  for (const Wall& w : walls) {
    const WallMotion& m = w.motion;
    out.push_back({{"name", w.name}, {"origin", vec_json(w.origin)}, {"normal", vec_json(w.normal)},
                   {"material", w.material}, {"bounded", w.bounded}, {"axis_u", vec_json(w.axis_u)},
                   {"axis_v", vec_json(w.axis_v)}, {"half_extent_u", w.half_extent_u},
                   {"half_extent_v", w.half_extent_v}, {"motion_kind", static_cast<int>(m.kind)},
                   {"motion_start_time", time_or_null(m.start_time)}, {"motion_direction", vec_json(m.direction)},
                   {"motion_acceleration", m.acceleration}, {"motion_top_speed", m.top_speed}});
  }
  return out;
}

std::vector<Wall> json_walls(const nlohmann::json& j) {
  std::vector<Wall> out;
  for (const nlohmann::json& w : j) {
    Wall wall;
    wall.name = w.at("name").get<std::string>();
    wall.origin = json_vec(w.at("origin"));
    wall.normal = json_vec(w.at("normal"));
    wall.material = w.at("material").get<int>();
    wall.bounded = w.at("bounded").get<bool>();
    wall.axis_u = json_vec(w.at("axis_u"));
    wall.axis_v = json_vec(w.at("axis_v"));
    wall.half_extent_u = w.at("half_extent_u").get<double>();
    wall.half_extent_v = w.at("half_extent_v").get<double>();
    const int kind = w.at("motion_kind").get<int>();
    if (kind < 0 || kind > static_cast<int>(WallMotion::Kind::accelerated))
      throw std::runtime_error("unknown wall motion " + std::to_string(kind));
    wall.motion.kind = static_cast<WallMotion::Kind>(kind);
    wall.motion.start_time = null_or_time(w.at("motion_start_time"));  // +inf: not opened yet
    wall.motion.direction = json_vec(w.at("motion_direction"));
    wall.motion.acceleration = w.at("motion_acceleration").get<double>();
    wall.motion.top_speed = w.at("motion_top_speed").get<double>();
    out.push_back(wall);
  }
  return out;
}

// ---- whole arrays, or one rank's rows of them ----

using Rows = std::optional<Hdf5Reader::Rows>;  // none: the whole dataset, checked against its checksum

std::vector<double> read_doubles(const Hdf5Reader& h5, const std::string& path, std::size_t columns, const Rows& rows) {
  return rows ? h5.read_double_rows(path, columns, *rows) : h5.read_double(path, columns);
}
std::vector<std::uint32_t> read_u32s(const Hdf5Reader& h5, const std::string& path, std::size_t columns, const Rows& rows) {
  return rows ? h5.read_u32_rows(path, columns, *rows) : h5.read_u32(path, columns);
}
std::vector<std::int32_t> read_i32s(const Hdf5Reader& h5, const std::string& path, const Rows& rows) {
  return rows ? h5.read_i32_rows(path, 1, *rows) : h5.read_i32(path);
}
std::vector<std::uint16_t> read_u16s(const Hdf5Reader& h5, const std::string& path, std::size_t columns, const Rows& rows) {
  return rows ? h5.read_u16_rows(path, columns, *rows) : h5.read_u16(path, columns);
}

// ---- contact memories and contact points ----

void write_memory(Hdf5Writer& h5, const std::string& group, const ContactMemory& m) {
  h5.write(group + "/spring", flat(m.spring), 3);
  h5.write(group + "/normal_prev", flat(m.normal_prev), 3);
  h5.write(group + "/rolling", flat(m.rolling), 3);
}

ContactMemory read_memory(const Hdf5Reader& h5, const std::string& group, const Rows& rows) {
  // A model that keeps no memory of a kind stores none: no rows to take a share of.
  const auto column = [&](const char* name) {
    const std::string path = group + "/" + name;
    return vec3s(read_doubles(h5, path, 3, h5.rows(path, 3) == 0 ? Rows{} : rows));
  };
  ContactMemory m;
  m.spring = column("spring");
  m.normal_prev = column("normal_prev");
  m.rolling = column("rolling");
  return m;
}

// Contact points of every entry in one table each: per entry how many, then the points in turn.
void write_points(Hdf5Writer& h5, const std::string& group, const std::vector<SubContactList>& lists) {
  std::vector<std::uint32_t> count, feature;
  std::vector<std::uint16_t> part;
  std::vector<Vec3> spring, normal_prev, point, force;
  std::vector<double> overlap, share;
  for (const SubContactList& list : lists) {
    count.push_back(static_cast<std::uint32_t>(list.size()));
    for (const SubContact& s : list) {
      part.insert(part.end(), {s.part_i, s.part_j});
      feature.push_back(s.feature);
      spring.push_back(s.spring);
      normal_prev.push_back(s.normal_prev);
      point.push_back(s.point);
      force.push_back(s.force);
      overlap.push_back(s.overlap);
      share.push_back(s.share);
    }
  }
  h5.write(group + "/count", count);
  h5.write(group + "/part", part, 2);
  h5.write(group + "/feature", feature);
  h5.write(group + "/spring", flat(spring), 3);
  h5.write(group + "/normal_prev", flat(normal_prev), 3);
  h5.write(group + "/point", flat(point), 3);
  h5.write(group + "/force", flat(force), 3);
  h5.write(group + "/overlap", overlap);
  h5.write(group + "/share", share);
}

// `entries`: one rank's entries, whose points follow those of the entries before them.
std::vector<SubContactList> read_points(const Hdf5Reader& h5, const std::string& group, const Rows& entries) {
  Rows rows;  // of the point tables
  std::vector<std::uint32_t> count;
  if (entries && h5.rows(group + "/count") > 0) {
    const std::vector<std::uint32_t> before = h5.read_u32_rows(group + "/count", 1, {0, entries->first});
    count = h5.read_u32_rows(group + "/count", 1, *entries);
    rows = Hdf5Reader::Rows{std::accumulate(before.begin(), before.end(), std::size_t{0}),
                            std::accumulate(count.begin(), count.end(), std::size_t{0})};
  } else {
    count = h5.read_u32(group + "/count");  // whole, or none stored (spheres)
  }
  const std::vector<std::uint16_t> part = read_u16s(h5, group + "/part", 2, rows);
  const std::vector<std::uint32_t> feature = read_u32s(h5, group + "/feature", 1, rows);
  const std::vector<Vec3> spring = vec3s(read_doubles(h5, group + "/spring", 3, rows));
  const std::vector<Vec3> normal_prev = vec3s(read_doubles(h5, group + "/normal_prev", 3, rows));
  const std::vector<Vec3> point = vec3s(read_doubles(h5, group + "/point", 3, rows));
  const std::vector<Vec3> force = vec3s(read_doubles(h5, group + "/force", 3, rows));
  const std::vector<double> overlap = read_doubles(h5, group + "/overlap", 1, rows);
  const std::vector<double> share = read_doubles(h5, group + "/share", 1, rows);
  std::size_t total = 0;
  for (std::uint32_t c : count) total += c;
  const std::size_t n = feature.size();
  if (total != n || part.size() != 2 * n || spring.size() != n || normal_prev.size() != n || point.size() != n ||
      force.size() != n || overlap.size() != n || share.size() != n)
    throw std::runtime_error(h5.path().string() + ": " + group + ": contact point tables of different lengths");
  std::vector<SubContactList> lists(count.size());
  std::size_t k = 0;
  for (std::size_t e = 0; e < lists.size(); ++e)
    for (std::uint32_t c = 0; c < count[e]; ++c, ++k) {
      SubContact s;
      s.part_i = part[2 * k];
      s.part_j = part[2 * k + 1];
      s.feature = feature[k];
      s.spring = spring[k];
      s.normal_prev = normal_prev[k];
      s.point = point[k];
      s.force = force[k];
      s.overlap = overlap[k];
      s.share = share[k];
      lists[e].push_back(s);
    }
  return lists;
}

// ---- the World ----

void write_world(Hdf5Writer& h5, const WorldState& s) {
  const ParticleStore& p = s.particles;
  h5.write("world/counters", std::vector<std::uint64_t>{s.next_gid, s.steps, s.rebuilds,
                                                       static_cast<std::uint64_t>(s.tangential_model), s.ranks});
  h5.write("world/times", std::vector<double>{s.time, s.time_at_build, s.skin, s.gravity.x, s.gravity.y, s.gravity.z});
  h5.write("world/particles/position", flat(p.position), 3);
  h5.write("world/particles/velocity", flat(p.velocity), 3);
  h5.write("world/particles/angular_velocity", flat(p.angular_velocity), 3);
  h5.write("world/particles/force", flat(p.force), 3);
  h5.write("world/particles/torque", flat(p.torque), 3);
  h5.write("world/particles/orientation", flat(p.orientation), 4);
  h5.write("world/particles/radius", p.radius);
  h5.write("world/particles/inv_mass", p.inv_mass);
  h5.write("world/particles/mass", p.mass);
  h5.write("world/particles/inv_inertia", flat(p.inv_inertia), 3);
  h5.write("world/particles/species", p.species);
  h5.write("world/particles/shape", p.shape);
  h5.write("world/particles/gid", p.gid);
  h5.write("world/position_at_build", flat(s.position_at_build), 3);
  h5.write_text("world/walls", walls_json(s.walls).dump());
  h5.write("world/wall_force", flat(s.wall_force), 3);

  std::vector<std::uint32_t> pair_gid;
  pair_gid.reserve(2 * s.pair_gid_i.size());
  for (std::size_t e = 0; e < s.pair_gid_i.size(); ++e) pair_gid.insert(pair_gid.end(), {s.pair_gid_i[e], s.pair_gid_j[e]});
  h5.write("contacts/pairs/gid", pair_gid, 2);
  write_memory(h5, "contacts/pairs", s.pair_memory);
  write_points(h5, "contacts/pairs/points", s.pair_sub);
  h5.write("contacts/walls/gid", s.wall_gid);
  h5.write("contacts/walls/wall", s.wall_index);
  h5.write("contacts/walls/force", flat(s.wall_entry_force), 3);
  write_memory(h5, "contacts/walls", s.wall_memory);
  write_points(h5, "contacts/walls/points", s.wall_sub);
  const WorldState::RankLayout& l = s.layout;
  if (!l.particles.empty()) {  // a state gathered from ranks: their layout, for a restart on as many
    // The cuts of the cut axes, x's first; `slabs`: the slab axis, whether the cuts follow the
    // particles, the narrowest slab allowed, then the ranks along x, y and z.
    std::vector<double> cut, slabs{static_cast<double>(l.axis), l.rebalance ? 1.0 : 0.0, l.min_width};
    for (const std::vector<double>& c : l.cut) {
      cut.insert(cut.end(), c.begin(), c.end());
      slabs.push_back(c.empty() ? 1.0 : static_cast<double>(c.size() - 1));
    }
    h5.write("world/layout/cut", cut);
    h5.write("world/layout/slabs", slabs);
    std::vector<std::uint64_t> shares;
    for (std::size_t r = 0; r < l.particles.size(); ++r)
      shares.insert(shares.end(), {l.particles[r], l.pair_entries[r], l.wall_entries[r]});
    h5.write("world/layout/shares", shares, 3);
  }
}

// The rank layout of a state joined from ranks (none in a one-rank state).
void read_layout(const Hdf5Reader& h5, WorldState& s) {
  if (!h5.has("world/layout/cut")) return;
  WorldState::RankLayout& l = s.layout;
  const std::vector<double> cut = h5.read_double("world/layout/cut");
  std::vector<double> slabs = h5.read_double("world/layout/slabs");
  const std::vector<std::uint64_t> shares = h5.read_u64("world/layout/shares", 3);
  const auto damaged = [&h5] { return std::runtime_error(h5.path().string() + ": rank layout damaged"); };
  if (!(slabs.size() == 3 || slabs.size() == 6) || !(slabs[0] == 0 || slabs[0] == 1 || slabs[0] == 2) ||
      shares.size() != 3 * s.ranks)
    throw damaged();
  if (slabs.size() == 3) {  // slabs along one axis, as files written before grids of ranks
    slabs.resize(6, 1.0);
    slabs[3 + static_cast<int>(slabs[0])] = static_cast<double>(s.ranks);
  }
  std::size_t at = 0, grid = 1;
  for (int a = 0; a < 3; ++a) {
    const double n = slabs[3 + a];
    if (!(n >= 1 && n == std::floor(n) && n <= static_cast<double>(s.ranks))) throw damaged();
    grid *= static_cast<std::size_t>(n);
    if (n == 1) continue;
    if (at + static_cast<std::size_t>(n) + 1 > cut.size()) throw damaged();
    l.cut[a].assign(cut.begin() + static_cast<std::ptrdiff_t>(at), cut.begin() + static_cast<std::ptrdiff_t>(at + n + 1));
    at += static_cast<std::size_t>(n) + 1;
  }
  if (at != cut.size() || grid != s.ranks) throw damaged();
  l.axis = static_cast<int>(slabs[0]);
  l.rebalance = slabs[1] != 0;
  l.min_width = slabs[2];
  std::uint64_t particles = 0, pairs = 0, walls = 0;
  for (std::size_t r = 0; r < s.ranks; ++r) {
    l.particles.push_back(shares[3 * r]);
    l.pair_entries.push_back(shares[3 * r + 1]);
    l.wall_entries.push_back(shares[3 * r + 2]);
    particles += shares[3 * r], pairs += shares[3 * r + 1], walls += shares[3 * r + 2];
  }
  if (particles != h5.rows("world/particles/gid") || pairs != h5.rows("contacts/pairs/gid", 2) ||
      walls != h5.rows("contacts/walls/gid"))
    throw std::runtime_error(h5.path().string() + ": rank layout does not add up to the stored arrays");
}

// `share_of_rank` >= 0, with a layout that fits `ranks`: only that rank's rows of the joined
// arrays (WorldState::share_of_rank).
WorldState read_world(const Hdf5Reader& h5, int share_of_rank = -1, int ranks = 1) {
  WorldState s;
  const std::vector<std::uint64_t> counters = h5.read_u64("world/counters");
  const std::vector<double> times = h5.read_double("world/times");
  // A fifth counter, the ranks the state was gathered from, is absent from older files (one).
  if (counters.size() < 4 || counters.size() > 5 || times.size() != 6 ||
      counters[3] > static_cast<std::uint64_t>(TangentialModel::elastic_spring) ||
      (counters.size() == 5 && counters[4] == 0))
    throw std::runtime_error(h5.path().string() + ": world counters damaged");
  s.ranks = counters.size() == 5 ? counters[4] : 1;
  s.next_gid = static_cast<std::uint32_t>(counters[0]);
  s.steps = counters[1];
  s.rebuilds = counters[2];
  s.tangential_model = static_cast<TangentialModel>(counters[3]);
  s.time = times[0];
  s.time_at_build = times[1];
  s.skin = times[2];
  s.gravity = {times[3], times[4], times[5]};
  read_layout(h5, s);
  s.walls = json_walls(nlohmann::json::parse(h5.read_text("world/walls")));
  s.wall_force = vec3s(h5.read_double("world/wall_force", 3));

  Rows particles, pairs, walls;  // the rows this rank reads of each kind of array
  if (share_of_rank >= 0 && s.fits_ranks(static_cast<std::uint64_t>(ranks))) {
    const WorldState::RankLayout& l = s.layout;
    const auto share = [share_of_rank](const std::vector<std::uint64_t>& counts) {
      const auto r = static_cast<std::ptrdiff_t>(share_of_rank);
      return Hdf5Reader::Rows{std::accumulate(counts.begin(), counts.begin() + r, std::size_t{0}),
                              static_cast<std::size_t>(counts[static_cast<std::size_t>(r)])};
    };
    particles = share(l.particles), pairs = share(l.pair_entries), walls = share(l.wall_entries);
    s.share_of_rank = share_of_rank;
  }
  ParticleStore& p = s.particles;
  p.position = vec3s(read_doubles(h5, "world/particles/position", 3, particles));
  p.velocity = vec3s(read_doubles(h5, "world/particles/velocity", 3, particles));
  p.angular_velocity = vec3s(read_doubles(h5, "world/particles/angular_velocity", 3, particles));
  p.force = vec3s(read_doubles(h5, "world/particles/force", 3, particles));
  p.torque = vec3s(read_doubles(h5, "world/particles/torque", 3, particles));
  p.orientation = quats(read_doubles(h5, "world/particles/orientation", 4, particles));
  p.radius = read_doubles(h5, "world/particles/radius", 1, particles);
  p.inv_mass = read_doubles(h5, "world/particles/inv_mass", 1, particles);
  p.mass = read_doubles(h5, "world/particles/mass", 1, particles);
  p.inv_inertia = vec3s(read_doubles(h5, "world/particles/inv_inertia", 3, particles));
  p.species = read_i32s(h5, "world/particles/species", particles);
  p.shape = read_i32s(h5, "world/particles/shape", particles);
  p.gid = read_u32s(h5, "world/particles/gid", 1, particles);
  p.owned = p.position.size();
  s.position_at_build = vec3s(read_doubles(h5, "world/position_at_build", 3, particles));

  const std::vector<std::uint32_t> pair_gid = read_u32s(h5, "contacts/pairs/gid", 2, pairs);
  for (std::size_t e = 0; 2 * e < pair_gid.size(); ++e) {
    s.pair_gid_i.push_back(pair_gid[2 * e]);
    s.pair_gid_j.push_back(pair_gid[2 * e + 1]);
  }
  s.pair_memory = read_memory(h5, "contacts/pairs", pairs);
  s.pair_sub = read_points(h5, "contacts/pairs/points", pairs);
  s.wall_gid = read_u32s(h5, "contacts/walls/gid", 1, walls);
  s.wall_index = read_i32s(h5, "contacts/walls/wall", walls);
  s.wall_entry_force = vec3s(read_doubles(h5, "contacts/walls/force", 3, walls));
  s.wall_memory = read_memory(h5, "contacts/walls", walls);
  s.wall_sub = read_points(h5, "contacts/walls/points", walls);
  return s;
}

}  // namespace

std::vector<char> checkpoint_image(const Checkpoint& c) {
  Hdf5Writer h5;
  h5.attribute("format", kFormat);
  h5.attribute("format_version", std::int64_t{kCheckpointFormatVersion});
  h5.attribute("talus_version", c.talus_version);
  h5.attribute("step", static_cast<std::int64_t>(c.world.steps));
  h5.write_text("scenario", c.scenario_toml);
  h5.write_text("run", c.run.dump());
  h5.write("timeseries", c.timeseries, std::max<std::size_t>(1, c.timeseries_columns.size()));
  h5.write_text("timeseries_columns", nlohmann::json(c.timeseries_columns).dump());
  write_world(h5, c.world);
  return h5.image();
}

void write_checkpoint(const std::filesystem::path& path, const Checkpoint& c) {
  if (!c.world.whole) throw std::logic_error("one rank's piece of a distributed state is not a checkpoint");
  const std::vector<char> bytes = checkpoint_image(c);
  atomic_write(path, std::string_view(bytes.data(), bytes.size()));
}

namespace {

// The talus version that wrote the file; InputError unless it is a checkpoint of this format.
std::string checked_writer(const Hdf5Reader& h5, const std::filesystem::path& path) {
  if (!h5.has_attribute("format") || h5.string_attribute("format") != kFormat)
    throw InputError(path.string() + ": not a Talus checkpoint (no format = \"" + kFormat + "\" attribute)");
  const std::int64_t version = h5.int_attribute("format_version");
  const std::string written_by = h5.has_attribute("talus_version") ? h5.string_attribute("talus_version") : "?";
  if (version != kCheckpointFormatVersion)
    throw InputError(path.string() + ": checkpoint format version " + std::to_string(version) + " (written by talus " +
                     written_by + "); this talus (" + TALUS_VERSION + ") reads version " +
                     std::to_string(kCheckpointFormatVersion));
  return written_by;
}

// read(h5) on the opened checkpoint, every failure an InputError that names the file.
template <class Read>
auto read_from(const std::filesystem::path& path, Read read) {
  try {
    Hdf5Reader h5(path);
    return read(h5);
  } catch (const InputError&) {
    throw;
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path.string() + ": damaged checkpoint: " + e.what());
  } catch (const std::exception& e) {
    // Hdf5Reader's messages already start with the path.
    const std::string what = e.what();
    throw InputError(what.rfind(path.string(), 0) == 0 ? what : path.string() + ": " + what);
  }
}

}  // namespace

Checkpoint read_checkpoint(const std::filesystem::path& path) { return read_checkpoint_share(path, -1, 1); }

Checkpoint read_checkpoint_share(const std::filesystem::path& path, int rank, int ranks) {
  return read_from(path, [&](const Hdf5Reader& h5) {
    Checkpoint c;
    c.talus_version = checked_writer(h5, path);
    c.scenario_toml = h5.read_text("scenario");
    c.run = nlohmann::json::parse(h5.read_text("run"));
    c.timeseries_columns = nlohmann::json::parse(h5.read_text("timeseries_columns")).get<std::vector<std::string>>();
    c.timeseries = h5.read_double("timeseries", std::max<std::size_t>(1, c.timeseries_columns.size()));
    c.world = read_world(h5, rank, ranks);
    return c;
  });
}

std::string read_checkpoint_scenario(const std::filesystem::path& path) {
  return read_from(path, [&path](const Hdf5Reader& h5) {
    checked_writer(h5, path);
    return h5.read_text("scenario");
  });
}

}  // namespace talus::io
