#pragma once
// Synthetic snapshots for the coarse-graining tests: lattices and stacked columns whose
// fields are known in closed form.
#include <cmath>
#include <random>

#include "talus/analysis/snapshot.h"

namespace talus::cg_test {

inline ParticleRecord particle(const Vec3& x, double mass = 1, double radius = 0.5, bool fixed = false) {
  ParticleRecord p;
  p.position = x;
  p.mass = mass;
  p.radius = radius;
  p.fixed = fixed;
  p.volume = 4.0 / 3.0 * M_PI * radius * radius * radius;
  return p;
}

inline ContactRecord contact(int i, int j, const Vec3& point, const Vec3& force) {
  ContactRecord c;
  c.i = i;
  c.j = j;
  c.point = point;
  c.force = force;
  c.normal = normalized_or_zero(force);
  return c;
}

// A simple-cubic lattice nx x ny x nz of spacing a, particles at (i + 1/2) a, periodic in x
// and y (box [0, nx a] x [0, ny a]) and z in [0, nz a] (periodic if periodic_z).
inline Snapshot cubic_lattice(int nx, int ny, int nz, double a, double mass, bool periodic_z) {
  Snapshot s;
  s.domain_min = {0, 0, 0};
  s.domain_max = {nx * a, ny * a, nz * a};
  s.periodic[0] = s.periodic[1] = true;
  s.periodic[2] = periodic_z;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        s.particles.push_back(particle({(i + 0.5) * a, (j + 0.5) * a, (k + 0.5) * a}, mass, 0.5 * a));
  return s;
}

// nx x ny columns of nz touching spheres (diameter d) standing on a layer of fixed spheres at
// z = d/2, under gravity g along -z; each contact carries the weight of everything above it,
// so every flowing particle is in equilibrium. Flowing layer k sits at z = (k + 1.5) d.
inline Snapshot static_column(int nx, int ny, int nz, double d, double mass, double g) {
  Snapshot s;
  s.gravity = {0, 0, -g};
  s.domain_min = {0, 0, 0};
  s.domain_max = {nx * d, ny * d, (nz + 3) * d};
  s.periodic[0] = s.periodic[1] = true;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double x = (i + 0.5) * d, y = (j + 0.5) * d;
      int below = int(s.particles.size());
      s.particles.push_back(particle({x, y, 0.5 * d}, mass, 0.5 * d, true));
      for (int k = 0; k < nz; ++k) {
        const int self = int(s.particles.size());
        s.particles.push_back(particle({x, y, (k + 1.5) * d}, mass, 0.5 * d));
        // Force on the upper particle from the lower one: the weight of nz - k particles.
        s.contacts.push_back(contact(self, below, {x, y, (k + 1) * d}, {0, 0, (nz - k) * mass * g}));
        below = self;
      }
    }
  return s;
}

// A jittered simple-cubic packing with a contact between every pair of lattice neighbours
// (6 per particle), random forces and velocities: a stand-in for a dense flow snapshot.
// Periodic in x and y; the bottom layer also touches a wall at z = 0.
inline Snapshot jittered_packing(int nx, int ny, int nz, double a, unsigned seed) {
  Snapshot s = cubic_lattice(nx, ny, nz, a, 1.0, false);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  for (auto& p : s.particles) {
    p.position += Vec3{u(rng), u(rng), u(rng)} * (0.05 * a);
    p.velocity = Vec3{1 + 0.3 * u(rng), 0.3 * u(rng), 0.3 * u(rng)};
  }
  const auto id = [&](int i, int j, int k) { return i + nx * (j + ny * k); };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const int self = id(i, j, k);
        const int nbr[3] = {id((i + 1) % nx, j, k), id(i, (j + 1) % ny, k), k + 1 < nz ? id(i, j, k + 1) : -1};
        for (int n : nbr) {
          if (n < 0) continue;
          const Vec3 f{u(rng), u(rng), 2 + u(rng)};
          // Point roughly midway (wrapped), the branch is found by minimum image anyway.
          s.contacts.push_back(contact(self, n, s.particles[self].position, f));
        }
        if (k == 0) {
          const Vec3 x = s.particles[self].position;
          s.contacts.push_back(contact(self, -1, {x.x, x.y, 0}, {0.1 * u(rng), 0.1 * u(rng), 3}));
        }
      }
  return s;
}

}  // namespace talus::cg_test
