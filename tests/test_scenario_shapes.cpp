// Shapes from scenario files (shape_reader.h): a polyhedron of a box's corners moves as the box, a
// composite of two boxes is the built-in cross, a cylinder rolls down an incline at
// a = 2/3 g sin(theta), and malformed shapes are refused with their key.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "talus/io/input_error.h"
#include "talus/scenario/scenario.h"

namespace talus {
namespace {

// A scenario of one particle per entry of `species` (each a [species.NAME] table's text) over
// a floor; `extra` goes after the contact table.
std::string scene(const std::string& species_tables, const std::string& particles, const std::string& gravity = "[0.0, 0.0, -9.81]",
                  const std::string& contact = "") {
  return R"([run]
end_time = 0.1

[domain]
lo = [-1.0, -0.2, -0.1]
hi = [1.0, 0.2, 0.2]
gravity = )" + gravity + R"(

)" + species_tables + R"(
[contact]
model = "memory"
)" + contact + R"(
normal_stiffness = 1e4
normal_restitution = 0.3
tangential_stiffness_ratio = 0.2857142857142857
tangential_damping_factor = 0.0
friction = 0.5

[[walls]]
name = "floor"
point = [0.0, 0.0, 0.0]
normal = [0.0, 0.0, 1.0]
)" + particles;
}

std::string particle(const std::string& species, const Vec3& x, const std::string& orientation = "") {
  return "\n[[particles]]\nspecies = \"" + species + "\"\nposition = [" + std::to_string(x.x) + ", " + std::to_string(x.y) +
         ", " + std::to_string(x.z) + "]\n" + (orientation.empty() ? "" : "orientation = " + orientation + "\n");
}

Scenario load(const std::string& text) {
  io::ScenarioFile f = io::ScenarioFile::from_string(text, "case.toml");
  return load_scenario(f);
}

std::string load_error(const std::string& text) {
  try {
    load(text);
  } catch (const io::InputError& e) {
    return e.what();
  }
  return "";
}

void expect_same_body(const ParticleStore& p, std::size_t a, std::size_t b) {
  EXPECT_NEAR(p.mass[b], p.mass[a], 1e-12 * p.mass[a]);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(p.inv_inertia[b][k], p.inv_inertia[a][k], 1e-9 * p.inv_inertia[a][k]);
  EXPECT_NEAR(p.radius[b], p.radius[a], 1e-12);
}

TEST(ScenarioShapes, PolyhedronOfABoxsCornersIsTheBox) {
  const std::string species = R"([species.block]
shape = "box"
density = 700
half_extents = [0.01, 0.005, 0.0025]
crust = 2e-4

[species.hull]
shape = "polyhedron"
density = 700
crust = 2e-4
vertices = [[0.01, 0.005, 0.0025], [-0.01, 0.005, 0.0025], [0.01, -0.005, 0.0025], [-0.01, -0.005, 0.0025],
            [0.01, 0.005, -0.0025], [-0.01, 0.005, -0.0025], [0.01, -0.005, -0.0025], [-0.01, -0.005, -0.0025],
            [0.0, 0.0, 0.0]]   # an inner point, which the hull leaves out
)";
  // Both dropped tilted from 1 cm with face manifolds: the same bounces, the same rest, to
  // round-off (the polyhedron's faces are the box's).
  const std::string tilted = "[0.99, 0.1, 0.05, 0.0]";
  Scenario sc = load(scene(species, particle("block", {-0.1, 0, 0.01}, tilted) + particle("hull", {0.1, 0, 0.01}, tilted),
                           "[0.0, 0.0, -9.81]", "manifold = true"));
  World& w = *sc.world;
  expect_same_body(w.particles(), 0, 1);  // mass 700 x 0.02 x 0.01 x 0.005 kg, the box's moments
  EXPECT_NEAR(w.particles().mass[0], 700 * 0.02 * 0.01 * 0.005, 1e-15);
  w.run(20000);
  const ParticleStore& p = w.particles();
  EXPECT_LT(norm(p.position[1] - p.position[0] - Vec3{0.2, 0, 0}), 1e-12);
  EXPECT_LT(norm(p.velocity[1] - p.velocity[0]), 1e-12);
  EXPECT_LT(norm(p.angular_velocity[1] - p.angular_velocity[0]), 1e-10);
  EXPECT_NEAR(p.position[1].z, 0.0025, 1e-5);  // at rest on its large face
  EXPECT_LT(norm(p.velocity[1]), 1e-4);
}

TEST(ScenarioShapes, CompositeOfTwoBoxesIsTheCross) {
  const std::string species = R"([species.cross]
shape = "cross"
density = 2500
crust = 1e-4

[species.glued]
shape = "composite"
density = 2500

[[species.glued.parts]]
shape = "box"
half_extents = [0.0135, 0.001, 0.0015]
crust = 1e-4

[[species.glued.parts]]
shape = "box"
half_extents = [0.0135, 0.001, 0.0015]
crust = 1e-4
orientation = [0.7071067811865476, 0.0, 0.0, 0.7071067811865476]   # 90 degrees about z
)";
  Scenario sc = load(scene(species, particle("cross", {-0.1, 0, 0.01}) + particle("glued", {0.1, 0, 0.01})));
  expect_same_body(sc.world->particles(), 0, 1);
  // V = 2 x 27 x 2 x 3 - 2 x 2 x 3 mm^3 (the crossing counted once).
  EXPECT_NEAR(sc.world->particles().mass[1], 2500 * 312e-9, 1e-12);
}

// A solid cylinder rolling without slipping (tan(theta) <= 3 mu) accelerates at 2/3 g sin(theta).
TEST(ScenarioShapes, CylinderRollsDownAnInclineAtTwoThirdsGSinTheta) {
  const double theta = 20 * std::numbers::pi / 180, g = 9.81;
  const std::string gravity = "[" + std::to_string(g * std::sin(theta)) + ", 0.0, " + std::to_string(-g * std::cos(theta)) + "]";
  const std::string species = R"([species.roller]
shape = "cylinder"
density = 2500
radius = 0.01
height = 0.02
crust = 5e-4
)";
  // Its axis (local z) along y: turned by 90 degrees about x.
  Scenario sc = load(scene(species, particle("roller", {0, 0, 0.01}, "[0.7071067811865476, 0.7071067811865476, 0.0, 0.0]"), gravity));
  // Its mass properties as `talus check` prints them: m = pi r^2 h rho, I = m r^2 / 2 about the
  // axis and m (3 r^2 + h^2) / 12 across.
  const nlohmann::json& roller = sc.derived["species"]["roller"];
  const double m = std::numbers::pi * 1e-4 * 0.02 * 2500;
  EXPECT_NEAR(roller["mass"].get<double>(), m, 1e-12 * m);
  EXPECT_NEAR(roller["principal_moments"][0].get<double>(), 0.5 * m * 1e-4, 1e-12 * m * 1e-4);
  EXPECT_NEAR(roller["principal_moments"][2].get<double>(), m * (3e-4 + 4e-4) / 12, 1e-12 * m * 1e-4);
  World& w = *sc.world;
  w.run(2000);  // the contact settles
  const double t1 = w.time(), v1 = w.particles().velocity[0].x;
  w.run(8000);
  const double t2 = w.time(), v2 = w.particles().velocity[0].x;
  const double expected = 2.0 / 3.0 * g * std::sin(theta);
  EXPECT_NEAR((v2 - v1) / (t2 - t1) / expected, 1.0, 0.01);
  EXPECT_NEAR(w.particles().position[0].z, 0.01, 2e-4);  // rolling, not hopping
}

// The named shapes' volumes against their closed forms: a hexapod of three w x w x L rods
// 3 L w^2 - 2 w^3 (exact: its arms are boxes along the axes); a stellated octahedron in a cube
// of side 2a, two tetrahedra of 8a^3/3 sharing an octahedron of 4a^3/3, 4 a^3; a rod
// pi r^2 L + 4/3 pi r^3; a tetrapod, a hub ball of radius R = 5r/4 and four arms of radius r
// from s = 3r/4 to L, each arm's inner end a cap of height R - s inside the ball:
// 4/3 pi R^3 + 4 pi r^2 (L - s) - 4/3 pi h^2 (3R - h), with every principal moment
// 2/3 rho J (tetrahedral symmetry), J = integral of |x|^2: ball 4/5 pi R^5, arm
// pi r^2 (L^3 - s^3)/3 + pi r^4 (L - s)/2, cap pi/2 (R^4 (R - s) - (R^5 - s^5)/5).
// All four count their overlaps exactly (mass_properties.h).
TEST(ScenarioShapes, NamedShapesHaveTheirVolumes) {
  const std::string species = R"([species.hexapod]
shape = "hexapod"
density = 1000
length = 0.03
width = 0.004

[species.star]
shape = "stellated_octahedron"
density = 1000
size = 0.02

[species.rod]
shape = "rod"
density = 1000
length = 0.03
radius = 0.003

[species.tetrapod]
shape = "tetrapod"
density = 1000
length = 0.015
radius = 0.002
)";
  Scenario sc = load(scene(species, particle("hexapod", {-0.5, 0, 0.05}) + particle("star", {-0.2, 0, 0.05}) +
                                        particle("rod", {0.1, 0, 0.05}) + particle("tetrapod", {0.4, 0, 0.05})));
  const nlohmann::json& s = sc.derived["species"];
  const double pi = std::numbers::pi;
  EXPECT_NEAR(s["hexapod"]["volume"].get<double>(), 3 * 0.03 * 16e-6 - 2 * 64e-9, 1e-15);
  EXPECT_NEAR(s["star"]["volume"].get<double>() / (4 * 1e-6), 1.0, 1e-12);
  EXPECT_NEAR(s["rod"]["volume"].get<double>() / (pi * 9e-6 * 0.03 + 4.0 / 3.0 * pi * 27e-9), 1.0, 1e-12);
  const double r = 0.002, L = 0.015, start = 0.75 * r, R = 1.25 * r, h = R - start;
  EXPECT_NEAR(s["tetrapod"]["volume"].get<double>() /
                  (4.0 / 3.0 * pi * R * R * R + 4 * pi * r * r * (L - start) - 4 * pi * h * h * (3 * R - h) / 3),
              1.0, 1e-12);
  const double arm_j = pi * r * r * (L * L * L - start * start * start) / 3 + pi * r * r * r * r * (L - start) / 2;
  const double cap_j = pi / 2 * (std::pow(R, 4) * (R - start) - (std::pow(R, 5) - std::pow(start, 5)) / 5);
  const double j = 4 * pi * std::pow(R, 5) / 5 + 4 * arm_j - 4 * cap_j;
  for (const auto& moment : s["tetrapod"]["principal_moments"]) EXPECT_NEAR(moment.get<double>() / (2.0 / 3.0 * 1000 * j), 1.0, 1e-12);
}

// A regular tetrahedron (edge 2 cm) dropped tilted from 1 cm comes to rest on a face: its centre
// of mass a quarter of its height above the floor, one face's normal pointing straight down.
// With face manifolds (contact.manifold): one point per part pair leaves it chattering on its
// face at 2.5 mm/s.
TEST(ScenarioShapes, TetrahedronComesToRestOnAFace) {
  const std::string species = R"([species.tetra]
shape = "polyhedron"
density = 2500
crust = 2e-4
vertices = [[0.00707107, 0.00707107, 0.00707107], [0.00707107, -0.00707107, -0.00707107],
            [-0.00707107, 0.00707107, -0.00707107], [-0.00707107, -0.00707107, 0.00707107]]
)";
  Scenario sc = load(scene(species, particle("tetra", {0, 0, 0.02}, "[0.96, 0.2, 0.1, 0.15]"), "[0.0, 0.0, -9.81]", "manifold = true"));
  World& w = *sc.world;
  w.run(static_cast<std::uint64_t>(1.2 / w.settings().time_step));
  const ParticleStore& p = w.particles();
  const double edge = 0.02, height = edge * std::sqrt(2.0 / 3.0);
  EXPECT_NEAR(p.position[0].z, height / 4, 2e-4);  // within the crust's rounding
  EXPECT_LT(norm(p.velocity[0]), 1e-3);
  // The face opposite each corner has its outward normal along minus that corner's direction.
  double lowest = 1;
  for (const Vec3& corner : {Vec3{1, 1, 1}, Vec3{1, -1, -1}, Vec3{-1, 1, -1}, Vec3{-1, -1, 1}}) {
    const Vec3 normal = p.orientation[0].rotate(-1.0 * corner / std::sqrt(3.0));
    lowest = std::min(lowest, normal.z);
  }
  // The body frame is the principal one, turned from the shape's; its faces are the same set.
  EXPECT_NEAR(lowest, -1.0, 1e-3);
}

// A 2 cm cube given as a polyhedron on a 35 deg incline, friction 0.5 < tan 35: it slides at
// a = g (sin 35 - 0.5 cos 35) = 1.609 m/s^2.
TEST(ScenarioShapes, CubeSlidesDownAnIncline) {
  const double theta = 35 * std::numbers::pi / 180, g = 9.81;
  const std::string gravity = "[" + std::to_string(g * std::sin(theta)) + ", 0.0, " + std::to_string(-g * std::cos(theta)) + "]";
  const std::string species = R"([species.cube]
shape = "polyhedron"
density = 700
crust = 2e-4
vertices = [[0.01, 0.01, 0.01], [-0.01, 0.01, 0.01], [0.01, -0.01, 0.01], [-0.01, -0.01, 0.01],
            [0.01, 0.01, -0.01], [-0.01, 0.01, -0.01], [0.01, -0.01, -0.01], [-0.01, -0.01, -0.01]]
)";
  Scenario sc = load(scene(species, particle("cube", {0, 0, 0.01}), gravity, "manifold = true"));
  World& w = *sc.world;
  w.run(2000);
  const double t1 = w.time(), v1 = w.particles().velocity[0].x;
  w.run(6000);
  const double t2 = w.time(), v2 = w.particles().velocity[0].x;
  const double expected = g * (std::sin(theta) - 0.5 * std::cos(theta));
  EXPECT_NEAR((v2 - v1) / (t2 - t1) / expected, 1.0, 0.01);
  EXPECT_LT(norm(w.particles().angular_velocity[0]), 0.1);  // sliding flat, not tumbling
}

TEST(ScenarioShapes, MalformedShapesAreNamed) {
  const std::string flat = R"([species.hull]
shape = "polyhedron"
density = 700
vertices = [[0.0, 0.0, 0.0], [0.01, 0.0, 0.0], [0.0, 0.01, 0.0], [0.01, 0.01, 0.0]]
)";
  EXPECT_NE(load_error(scene(flat, particle("hull", {0, 0, 0.01}))).find("species.hull.vertices: the vertices lie in a plane"),
            std::string::npos);
  const std::string three = R"([species.hull]
shape = "polyhedron"
density = 700
vertices = [[0.0, 0.0, 0.0], [0.01, 0.0, 0.0], [0.0, 0.01, 0.0]]
)";
  EXPECT_NE(load_error(scene(three, particle("hull", {0, 0, 0.01}))).find("species.hull.vertices: a polyhedron needs at least 4"),
            std::string::npos);
  const std::string thick_crust = R"([species.roller]
shape = "cylinder"
density = 2500
radius = 0.01
height = 0.004
crust = 0.003
)";
  EXPECT_NE(load_error(scene(thick_crust, particle("roller", {0, 0, 0.01}))).find("species.roller.crust: must be smaller"),
            std::string::npos);
  const std::string empty = R"([species.glued]
shape = "composite"
density = 2500
)";
  EXPECT_NE(load_error(scene(empty, particle("glued", {0, 0, 0.01}))).find("species.glued.parts: a composite needs at least one part"),
            std::string::npos);
  const std::string odd = R"([species.glued]
shape = "composite"
density = 2500

[[species.glued.parts]]
shape = "cone"
radius = 0.01
)";
  EXPECT_NE(load_error(scene(odd, particle("glued", {0, 0, 0.01}))).find("species.glued.parts[0].shape"), std::string::npos);
}

}  // namespace
}  // namespace talus
