#pragma once
// Circumsphere of a Delaunay tetrahedron: the Voronoi vertex dual to it, i.e. a candidate
// pole. A construction (a rounded double point), never a decision.

#include "rstruct/geometry/vec3.hpp"

namespace rstruct::poles::detail {

struct Circumsphere {
  Vec3 offset;          ///< centre − a (kept relative to a for accuracy far from the origin)
  double squared_radius; ///< |offset|²
};

/// Circumsphere of the tetrahedron abcd (triangulation::orthosphere_offset with zero
/// weights). Well-shaped tetrahedra use floating point
/// (relative error of the centre a small multiple of 2⁻²⁶ of the circumradius); when the
/// volume is tiny relative to the edge lengths (slivers, nearly flat) the centre is computed
/// exactly with rationals and rounded once.
/// \pre orient3d(a, b, c, d) != 0 (the triangulation never creates flat tetrahedra).
/// \throws InternalError if abcd is flat.
Circumsphere circumsphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d);

}  // namespace rstruct::poles::detail
