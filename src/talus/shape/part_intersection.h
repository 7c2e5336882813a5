#pragma once
// The common volume of some parts of a composite, in closed form where one exists: the exact
// terms of mass_properties' inclusion-exclusion over overlapping parts.
//   - any number of polyhedral parts (boxes, polyhedra): their intersection is a convex
//     polyhedron, the hull of the vertices where three face planes meet inside every part;
//   - two spheres: a lens, two spherical caps;
//   - a sphere on a cylinder's axis past one of its caps, through the cap's rim or inside it:
//     a spherical cap (a half ball for a rod's end; the tetrapod's hub and arms);
//   - any two parts a positive distance apart (GJK, collide/gjk.h): nothing.
// Parts whose bounding boxes are apart meet in nothing. Anything else has no closed form here:
// nullopt, and the caller falls back to quadrature.
#include <optional>
#include <vector>

#include "talus/shape/composite_shape.h"
#include "talus/shape/volume_moments.h"

namespace talus {

// Moments (body frame) of the intersection of parts[subset]; volume 0 when they do not meet.
std::optional<VolumeMoments> intersection_moments(const CompositeShape& c, const std::vector<int>& subset);

}  // namespace talus
