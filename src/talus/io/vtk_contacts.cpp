#include "talus/io/vtk_contacts.h"

#include <stdexcept>
#include <string>
#include <vector>

#include "talus/io/atomic_file.h"
#include "talus/io/vtk_xml.h"
#include "talus/world/domain.h"

namespace talus::io {

VtuGrid contacts_grid(const Snapshot& s) {
  Domain domain;
  domain.lo = s.domain_min;
  domain.hi = s.domain_max;
  for (int a = 0; a < 3; ++a) domain.periodic[a] = s.periodic[a];

  const std::size_t n = s.contacts.size();
  const auto particle_count = static_cast<int>(s.particles.size());
  VtuGrid grid;
  std::vector<Vec3> force(n), normal(n);
  std::vector<double> normal_force(n), tangential_force(n), overlap(n);
  std::vector<std::int32_t> ci(n), cj(n), wall(n);
  std::vector<std::uint8_t> periodic(n, 0);
  for (std::size_t k = 0; k < n; ++k) {
    const ContactRecord& c = s.contacts[k];
    if (c.i < 0 || c.i >= particle_count || c.j >= particle_count)
      throw std::out_of_range("write_contacts_vtu: contact " + std::to_string(k) + " names particles " +
                              std::to_string(c.i) + ", " + std::to_string(c.j) + " of " +
                              std::to_string(particle_count));
    const Vec3 xi = s.particles[c.i].position;
    Vec3 end = c.point;
    if (c.j >= 0) {
      const Vec3 d = s.particles[c.j].position - xi;
      const Vec3 shortest = domain.any_periodic() ? domain.minimum_image(d) : d;
      periodic[k] = shortest == d ? 0 : 1;
      end = xi + shortest;
    }
    const std::int64_t a = grid.add_point(xi);
    const std::int64_t b = grid.add_point(end);
    grid.add_cell(VtkCellType::kLine, {a, b});

    force[k] = c.force;
    normal[k] = c.normal;
    normal_force[k] = dot(c.force, c.normal);
    tangential_force[k] = norm(c.force - c.normal * normal_force[k]);
    overlap[k] = c.overlap;
    ci[k] = static_cast<std::int32_t>(s.particles[c.i].id);
    cj[k] = c.j >= 0 ? static_cast<std::int32_t>(s.particles[c.j].id) : -1;
    wall[k] = c.j >= 0 ? -1 : c.wall;
  }
  using W = VtuGrid::Where;
  grid.add_array(W::kCell, "force", force);
  grid.add_array(W::kCell, "normal", normal);
  grid.add_array(W::kCell, "normal_force", 1, normal_force);
  grid.add_array(W::kCell, "tangential_force", 1, tangential_force);
  grid.add_array(W::kCell, "overlap", 1, overlap);
  grid.add_array(W::kCell, "i", 1, ci);
  grid.add_array(W::kCell, "j", 1, cj);
  grid.add_array(W::kCell, "wall", 1, wall);
  grid.add_array(W::kCell, "periodic", 1, periodic);
  return grid;
}

void write_contacts_vtu(const std::filesystem::path& path, const Snapshot& snapshot) {
  atomic_write(path, contacts_grid(snapshot).serialize());
}

}  // namespace talus::io
