#pragma once
// Named shapes of the granular literature, as composites of convex parts about the origin. The
// scenario reader builds its "hexapod", "tetrapod", "stellated_octahedron" and "rod" species with
// these (shape_reader.h), and tests and benchmarks can build the same bodies without a file.
// Each crust must stay below the shape's smallest half dimension, which *_smallest_half gives;
// scenario files default it to 5 % of that.
#include "talus/shape/composite_shape.h"

namespace talus {

// A 3-D cross: three square rods, length x width x width (m), along x, y and z, crossing at
// their centres.
double hexapod_smallest_half(double width);
CompositeShape make_hexapod(double length, double width, double crust);

// Four cylindrical arms of radius `radius` (m) towards a regular tetrahedron's corners, `arm`
// (m) from the centre to the flat end of each, on a hub ball of radius 1.25 radius through the
// arms' inner rims (the arms start 0.75 radius from the centre, where they no longer meet).
// arm > 1.25 radius.
double tetrapod_smallest_half(double arm, double radius);
CompositeShape make_tetrapod(double arm, double radius, double crust);

// Two regular tetrahedra in the corners of one cube of side `size` (m).
double stellated_octahedron_smallest_half(double size);
CompositeShape make_stellated_octahedron(double size, double crust);

// A spherocylinder along z: `length` (m) between its caps' centres.
double rod_smallest_half(double length, double radius);
CompositeShape make_rod(double length, double radius, double crust);

}  // namespace talus
