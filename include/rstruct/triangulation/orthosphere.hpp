#pragma once
/// \file
/// The sphere orthogonal to four weighted points (a, w_a) … (d, w_d): its centre z is the
/// power-diagram vertex dual to the cell abcd (the Voronoi vertex, circumcentre, when the
/// weights are 0). A construction — a rounded double, used for output and measurements,
/// never for a combinatorial decision.
///
/// With u = b − a, v = c − a, w = d − a and s_u = |u|² − w_b + w_a (likewise s_v, s_w), the
/// offset y = z − a solves 2 u·y = s_u, 2 v·y = s_v, 2 w·y = s_w; by Cramer's rule
/// y = (s_u v×w + s_v w×u + s_w u×v) / (2 u·(v×w)). Well-shaped cells use doubles (relative
/// error of y a small multiple of 2⁻²⁷ of |y|); when |u·(v×w)| < 2⁻²⁶·|u||v||w| (slivers and
/// nearly flat cells, where the double y can be off by many radii) y is computed exactly
/// over GMP rationals and rounded once per coordinate.

#include "rstruct/geometry/vec3.hpp"

namespace rstruct::triangulation {

/// z − a for the orthosphere of the four weighted points (weights are squared radii).
/// \pre abcd not flat (orient3d ≠ 0). \throws InternalError if it is.
Vec3 orthosphere_offset(const Point3& a, double wa, const Point3& b, double wb, const Point3& c,
                        double wc, const Point3& d, double wd);

}  // namespace rstruct::triangulation
