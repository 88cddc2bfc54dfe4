#pragma once
// The regular triangulation of a union of balls used by the medial module: the balls plus
// four far points of weight 0, so that any number of balls (coplanar centres included)
// spans R³, and K restricted to the balls.

#include <array>
#include <span>

#include "rstruct/complex/dual_complex.hpp"
#include "rstruct/complex/simplicial_complex.hpp"
#include "rstruct/geometry/vec3.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"

namespace rstruct::medial {

/// Four points at 16 times the extent of the balls from their box centre (double).
std::array<Point3, 4> far_points(std::span<const Ball> balls);

/// \throws InvalidInput if a centre or radius is not finite or a radius is not positive.
void check_balls(std::span<const Ball> balls);

/// Regular triangulation of the balls (ids 0..n−1) and the far points (ids n..n+3).
/// \pre !balls.empty().
triangulation::RegularTriangulation3 ball_triangulation(std::span<const Ball> balls);

/// K without the far points (which are isolated vertices of K).
complex::SimplicialComplex ball_complex(const complex::DualComplex& k, std::size_t n);

}  // namespace rstruct::medial
