#include "chute_state.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "talus/contact/head_on_impact.h"
#include "talus/contact/parameter_procedure.h"

namespace talus::bench {

namespace {

constexpr char kMagic[8] = {'T', 'A', 'L', 'U', 'S', 'C', 'H', 'T'};
constexpr std::uint32_t kVersion = 1;

// FNV-1a, 64 bit: a cache key and a checksum, not a cryptographic hash.
struct Fnv {
  std::uint64_t h = 1469598103934665603ull;
  void bytes(const void* data, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(data);
    for (std::size_t k = 0; k < n; ++k) h = (h ^ b[k]) * 1099511628211ull;
  }
  void num(double x) { bytes(&x, sizeof x); }
};

void hash_damping(Fnv& f, const DampingLaw& d) {
  f.num(d.coefficient);
  f.num(d.per_reduced_mass);
  f.num(d.per_sqrt_reduced_mass);
}

void hash_contact(Fnv& f, const ContactParams& c) {
  f.num(c.normal_stiffness);
  hash_damping(f, c.normal_damping);
  f.num(c.tangential_stiffness);
  hash_damping(f, c.tangential_damping);
  f.num(c.friction);
  f.num(c.rolling.enabled ? 1 : 0);
  f.num(c.rolling.friction);
  f.num(c.rolling.from_normal ? 1 : 0);
  f.num(c.rolling.stiffness);
  f.num(c.rolling.damping);
}

std::uint64_t case_key(const ChuteCase& c) {
  const ChuteSetup& s = c.setup;
  Fnv f;
  for (double x : {s.length, s.width, s.base_diameter, s.fill_height, s.angle_deg, s.diameter, s.density,
                   static_cast<double>(s.model), s.time_step, static_cast<double>(s.seed), c.flow_time})
    f.num(x);
  hash_contact(f, s.flow);
  hash_contact(f, s.base);
  return f.h;
}

// Fixed little-endian-host record layout, field by field (no struct padding in the file).
class Writer {
 public:
  template <class T> void put(const T& v) {
    const auto* b = reinterpret_cast<const char*>(&v);
    buf_.insert(buf_.end(), b, b + sizeof v);
  }
  void put(const Vec3& v) { put(v.x); put(v.y); put(v.z); }
  void put(const Quat& q) { put(q.w); put(q.x); put(q.y); put(q.z); }
  const std::vector<char>& buffer() const { return buf_; }

 private:
  std::vector<char> buf_;
};

// Reads the file as a stream (no whole-file buffer, so that a memory probe sees the world
// alone) and hashes what it reads, to check against the trailing checksum.
class Reader {
 public:
  explicit Reader(const std::filesystem::path& file) : in_(file, std::ios::binary) {
    if (!in_) throw std::runtime_error("chute cache: cannot open " + file.string());
  }
  template <class T> void get(T& v) {
    raw(v);
    sum_.bytes(&v, sizeof v);
  }
  void get(Vec3& v) { get(v.x); get(v.y); get(v.z); }
  void get(Quat& q) { get(q.w); get(q.x); get(q.y); get(q.z); }
  template <class T> void raw(T& v) {
    if (!in_.read(reinterpret_cast<char*>(&v), sizeof v)) throw std::runtime_error("chute cache: truncated file");
  }
  std::uint64_t sum() const { return sum_.h; }

 private:
  std::ifstream in_;
  Fnv sum_;
};

}  // namespace

ChuteCase make_case(const std::string& name, double length, double width, double fill_height, double flow_time) {
  ChuteCase c;
  c.name = name;
  c.setup.flow = c.setup.base = weinhart_chute_contact();
  c.setup.length = length;
  c.setup.width = width;
  c.setup.fill_height = fill_height;
  c.setup.angle_deg = 24;
  c.flow_time = flow_time;
  return c;
}

ContactParams hertz_mindlin_chute_contact() {
  // t_c = 2.868 (m*^2 / (R* E*^2 v))^(1/5) = 0.00497 at m* = 1/2, R* = 1/4, v = 1: E* = 8.0e6.
  const double poisson = 0.3, e_star = std::pow(2.868 / 0.00497, 2.5);
  const ElasticModuli moduli = elastic_moduli(2 * (1 - poisson * poisson) * e_star, poisson, false);
  ContactParams c = weinhart_chute_contact();
  c.normal_law = normal_law_index<HertzNormal>();
  c.damping_scaling = DampingScaling::tsuji;
  c.tangential_law = TangentialStiffness::mindlin;
  c.clamp = NormalClamp::free;
  c.impact_speed = 1;
  c.normal_stiffness = hertz_stiffness(moduli);
  c.tangential_stiffness = mindlin_stiffness(moduli);
  c.normal_damping = {};
  c.normal_damping.per_sqrt_reduced_mass =
      params::damping_for_restitution(c.normal_law, false, 0.883) * std::sqrt(c.normal_stiffness);
  c.tangential_damping = c.normal_damping;
  return c;
}

std::unique_ptr<World> make_empty_chute_world(const ChuteSetup& s) { return make_chute_world(s); }

std::filesystem::path cache_path(const std::filesystem::path& dir, const ChuteCase& c) {
  const ChuteSetup& s = c.setup;
  char name[160];
  std::snprintf(name, sizeof name, "chute_%gx%g_H%g_%gdeg_t%g_%016llx.v%u.bin", s.length, s.width, s.fill_height,
                s.angle_deg, c.flow_time, static_cast<unsigned long long>(case_key(c)), kVersion);
  return dir / name;
}

void save_state(const World& world, const std::filesystem::path& file) {
  const ParticleStore& p = world.particles();
  std::vector<std::uint32_t> order(p.owned);
  for (std::size_t i = 0; i < p.owned; ++i) order[i] = static_cast<std::uint32_t>(i);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return p.gid[a] < p.gid[b]; });

  Writer w;
  for (char ch : kMagic) w.put(ch);
  w.put(kVersion);
  w.put(world.time());
  w.put(static_cast<std::uint64_t>(p.owned));
  for (std::uint32_t i : order) {
    w.put(p.position[i]);
    w.put(p.velocity[i]);
    w.put(p.angular_velocity[i]);
    w.put(p.orientation[i]);
    w.put(p.radius[i]);
    w.put(p.mass[i]);
    w.put(p.inv_inertia[i]);
    w.put(p.species[i]);
    w.put(p.shape[i]);
    w.put(static_cast<std::uint8_t>(p.is_fixed(i)));
  }
  Fnv sum;
  sum.bytes(w.buffer().data(), w.buffer().size());
  w.put(sum.h);

  std::filesystem::create_directories(file.parent_path());
  const std::filesystem::path tmp = file.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out.write(w.buffer().data(), static_cast<std::streamsize>(w.buffer().size()));
    if (!out) throw std::runtime_error("chute cache: cannot write " + tmp.string());
  }
  std::filesystem::rename(tmp, file);
}

std::unique_ptr<World> load_state(const ChuteCase& c, const std::filesystem::path& file) {
  return load_state(make_empty_chute_world(c.setup), file);
}

namespace {

// Adds the file's particles to `world`, once per tile, each copy shifted by whole tiles of
// `tile` (x, y); returns the state's time.
double add_saved_particles(World& world, const std::filesystem::path& file, int tiles_x, int tiles_y, Vec3 tile) {
  Reader r(file);
  char magic[8];
  for (char& ch : magic) r.get(ch);
  std::uint32_t version;
  r.get(version);
  if (std::memcmp(magic, kMagic, 8) != 0 || version != kVersion)
    throw std::runtime_error("chute cache: not a version " + std::to_string(kVersion) + " file: " + file.string());
  double time;
  std::uint64_t n;
  r.get(time);
  r.get(n);

  std::vector<ParticleInit> inits(n);
  std::vector<Vec3> inv_inertias(n);
  for (std::uint64_t k = 0; k < n; ++k) {
    ParticleInit& init = inits[k];
    Vec3 inv_inertia;
    std::uint8_t fixed;
    r.get(init.position);
    r.get(init.velocity);
    r.get(init.angular_velocity);
    r.get(init.orientation);
    r.get(init.radius);
    r.get(init.mass);
    r.get(inv_inertia);
    r.get(init.species);
    r.get(init.shape);
    r.get(fixed);
    init.fixed = fixed != 0;
    const Vec3& ii = inv_inertia;
    init.inertia = init.fixed ? Vec3{1, 1, 1} : Vec3{1 / ii.x, 1 / ii.y, 1 / ii.z};  // ignored when fixed
    inv_inertias[k] = inv_inertia;
  }
  const std::uint64_t computed = r.sum();
  std::uint64_t stored;
  r.raw(stored);
  if (computed != stored) throw std::runtime_error("chute cache: checksum mismatch in " + file.string());

  world.reserve_particles(n * static_cast<std::size_t>(tiles_x * tiles_y));
  for (int tx = 0; tx < tiles_x; ++tx)
    for (int ty = 0; ty < tiles_y; ++ty)
      for (std::uint64_t k = 0; k < n; ++k) {
        ParticleInit init = inits[k];
        init.position += Vec3{tx * tile.x, ty * tile.y, 0};
        const std::uint32_t i = world.add_particle(init);
        // add_particle inverts the inertia again; restore the cached inverse bit for bit.
        world.particles_mutable().inv_inertia[i] = inv_inertias[k];
      }
  return time;
}

}  // namespace

std::unique_ptr<World> load_state(std::unique_ptr<World> world, const std::filesystem::path& file) {
  world->set_time(add_saved_particles(*world, file, 1, 1, Vec3{}));
  return world;
}

std::unique_ptr<World> load_state_tiled(const ChuteCase& c, const std::filesystem::path& file, int tiles_x,
                                        int tiles_y) {
  ChuteSetup large = c.setup;
  large.length *= tiles_x;
  large.width *= tiles_y;
  auto world = make_empty_chute_world(large);
  world->set_time(add_saved_particles(*world, file, tiles_x, tiles_y, Vec3{c.setup.length, c.setup.width, 0}));
  return world;
}

std::unique_ptr<World> load_or_generate(const ChuteCase& c, const std::filesystem::path& dir, int threads,
                                        double* seconds_generating) {
  if (seconds_generating) *seconds_generating = 0;
  const std::filesystem::path file = cache_path(dir, c);
  if (std::filesystem::exists(file)) return load_state(c, file);

  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  omp_set_num_threads(threads);
  std::fprintf(stderr, "[%s] no cache %s: building the chute and flowing it to t = %g on %d threads\n",
               c.name.c_str(), file.c_str(), c.flow_time, omp_get_max_threads());
  auto world = build_chute(c.setup);
  std::fprintf(stderr, "[%s] built %zu particles in %.1f s, dt = %.4g\n", c.name.c_str(), world->owned_count(),
               std::chrono::duration<double>(Clock::now() - t0).count(), world->settings().time_step);
  const double dt = world->settings().time_step;
  const auto steps = static_cast<std::uint64_t>(std::ceil(c.flow_time / dt - 1e-9));
  const std::uint64_t chunk = std::max<std::uint64_t>(1, steps / 10);
  for (std::uint64_t done = 0; done < steps;) {
    const std::uint64_t n = std::min(chunk, steps - done);
    world->run(n);
    done += n;
    const Diagnostics d = world->diagnostics();
    std::fprintf(stderr, "[%s] t = %.2f  mean speed %.3f  contacts %zu  (%.0f s)\n", c.name.c_str(), world->time(),
                 d.mean_speed, d.contacts, std::chrono::duration<double>(Clock::now() - t0).count());
  }
  save_state(*world, file);
  if (seconds_generating) *seconds_generating = std::chrono::duration<double>(Clock::now() - t0).count();
  std::fprintf(stderr, "[%s] cached %s\n", c.name.c_str(), file.c_str());
  // Continue from the file, so that the first run and every later one start from the same state.
  return load_state(c, file);
}

}  // namespace talus::bench
