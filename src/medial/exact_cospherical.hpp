#pragma once
// Whether four boundary vertices are coplanar, or five cospherical, decided on their exact
// points.
//
// Five sites of V on one sphere make one Voronoi vertex of several Delaunay cells. Where
// they lie on a common ball's sphere, the cells share that ball's centre and its key.
// Where the sphere is no ball's (symmetric unions: balls of a few radii on a grid), the
// rounded points are not exactly cospherical, so an insphere test on them splits the one
// Voronoi vertex into several, which the medial axis then keys apart. The exact points
// have coordinates a + b·√h (one square root per point), so the orientation and lifted
// insphere determinants lie in Q(√h₁, …, √h₅): they are computed there exactly, after the
// multiplicative relations among the roots are removed (a product of radicands that is a
// rational square makes one root a rational multiple of the others), which leaves
// monomials that are linearly independent over Q: a value is zero iff all its
// coefficients are.

#include <array>
#include <span>

#include "rstruct/geometry/vec3.hpp"
#include "rstruct/medial/boundary_vertices.hpp"

namespace rstruct::medial {

/// True iff the exact points of the four vertices are coplanar. Exact. Both tests first try
/// an interval enclosure of the exact points (outward rounding by one ulp per operation):
/// a determinant interval that excludes 0 decides "no" without rational arithmetic.
bool exactly_coplanar(const std::array<const BoundaryVertex*, 4>& v, std::span<const Ball> balls);

/// True iff the exact points of the five vertices lie on one sphere or plane (which holds
/// for any fifth point when the first four are concyclic). Exact.
bool exactly_cospherical(const std::array<const BoundaryVertex*, 5>& v, std::span<const Ball> balls);

/// A floating-point prefilter on rounded points: false only if the lifted insphere
/// determinant exceeds 10⁻⁸ of its magnitude bound (the sum of the absolute values of its
/// terms). The rounding of V is ≈ 10⁻¹⁶ relative, but its constructions can be
/// ill-conditioned: at 10⁻¹⁴, exactly cospherical points of a four-radii grid were missed.
/// A documented heuristic for speed: a case it skips is decided as before the exact tests
/// existed. (No such prefilter guards exactly_coplanar: one at 10⁻⁸ missed flat cells and
/// broke 7 of 70 four-radii grids.)
bool maybe_cospherical(const std::array<Point3, 5>& p);

}  // namespace rstruct::medial
