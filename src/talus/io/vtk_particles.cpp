#include "talus/io/vtk_particles.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "talus/io/atomic_file.h"
#include "talus/io/vtk_xml.h"
#include "talus/shape/pose.h"

namespace talus::io {

namespace {

// The particle data for a list of tuples, tuple k describing particle `which[k]`.
void add_particle_arrays(VtuGrid& grid, VtuGrid::Where where, const Snapshot& s,
                         const std::vector<std::size_t>& which) {
  const std::size_t n = which.size();
  std::vector<std::uint32_t> id(n);
  std::vector<std::int32_t> species(n), shape(n);
  std::vector<Vec3> velocity(n), angular_velocity(n);
  std::vector<double> orientation(4 * n), radius(n), mass(n);
  std::vector<std::uint8_t> fixed(n);
  for (std::size_t k = 0; k < n; ++k) {
    const ParticleRecord& p = s.particles[which[k]];
    id[k] = p.id;
    species[k] = p.species;
    shape[k] = p.shape;
    velocity[k] = p.velocity;
    angular_velocity[k] = p.angular_velocity;
    orientation[4 * k + 0] = p.orientation.w;
    orientation[4 * k + 1] = p.orientation.x;
    orientation[4 * k + 2] = p.orientation.y;
    orientation[4 * k + 3] = p.orientation.z;
    radius[k] = p.radius;
    mass[k] = p.mass;
    fixed[k] = p.fixed ? 1 : 0;
  }
  grid.add_array(where, "id", 1, id);
  grid.add_array(where, "species", 1, species);
  grid.add_array(where, "shape", 1, shape);
  grid.add_array(where, "velocity", velocity);
  grid.add_array(where, "angular_velocity", angular_velocity);
  grid.add_array(where, "orientation", 4, orientation);
  grid.add_array(where, "radius", 1, radius);
  grid.add_array(where, "mass", 1, mass);
  grid.add_array(where, "fixed", 1, fixed);
}

}  // namespace

VtuGrid particles_grid(const Snapshot& snapshot, std::size_t count) {
  VtuGrid grid;
  std::vector<std::size_t> all(std::min(count, snapshot.particles.size()));
  for (std::size_t i = 0; i < all.size(); ++i) {
    all[i] = i;
    const std::int64_t p = grid.add_point(snapshot.particles[i].position);
    grid.add_cell(VtkCellType::kVertex, {p});
  }
  add_particle_arrays(grid, VtuGrid::Where::kPoint, snapshot, all);
  return grid;
}

void write_particles_vtu(const std::filesystem::path& path, const Snapshot& snapshot) {
  atomic_write(path, particles_grid(snapshot, snapshot.particles.size()).serialize());
}

VtuGrid shapes_grid(const Snapshot& snapshot, std::size_t count, const std::vector<CompositeShape>& shapes,
                    const MeshResolution& resolution) {
  // One body-frame mesh per shape in use, built on first use.
  std::vector<SurfaceMesh> meshes(shapes.size());
  std::vector<char> built(shapes.size(), 0);

  VtuGrid grid;
  std::vector<std::size_t> owner;  // particle of each cell
  std::vector<std::int32_t> part;
  for (std::size_t i = 0; i < std::min(count, snapshot.particles.size()); ++i) {
    const ParticleRecord& p = snapshot.particles[i];
    if (p.shape < 0 || static_cast<std::size_t>(p.shape) >= shapes.size())
      throw std::out_of_range("write_shapes_vtu: particle " + std::to_string(p.id) + " has shape " +
                              std::to_string(p.shape) + " but the shape table has " +
                              std::to_string(shapes.size()) + " entries");
    const CompositeShape& shape = shapes[p.shape];
    if (is_plain_sphere(shape)) continue;
    if (!built[p.shape]) {
      meshes[p.shape] = triangulate(shape, resolution);
      built[p.shape] = 1;
    }
    const SurfaceMesh& m = meshes[p.shape];
    const Pose pose{p.position, p.orientation};
    const std::int64_t base = static_cast<std::int64_t>(grid.points());
    for (const Vec3& v : m.vertices) grid.add_point(pose.to_parent(v));
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
      const auto& tri = m.triangles[t];
      grid.add_cell(VtkCellType::kTriangle, {base + tri[0], base + tri[1], base + tri[2]});
      owner.push_back(i);
      part.push_back(m.part[t]);
    }
  }
  add_particle_arrays(grid, VtuGrid::Where::kCell, snapshot, owner);
  grid.add_array(VtuGrid::Where::kCell, "part", 1, part);
  return grid;
}

void write_shapes_vtu(const std::filesystem::path& path, const Snapshot& snapshot,
                      const std::vector<CompositeShape>& shapes, const MeshResolution& resolution) {
  atomic_write(path, shapes_grid(snapshot, snapshot.particles.size(), shapes, resolution).serialize());
}

}  // namespace talus::io
