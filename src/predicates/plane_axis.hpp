#pragma once
/// \file
/// Filtered 2D orientations in coordinate planes, and the choice of a coordinate plane in
/// which three points of a plane in R³ are not collinear (used by the coplanar and
/// collinear predicates and their perturbation).

#include "rstruct/geometry/vec3.hpp"

namespace rstruct::predicates::detail {

/// Exact sign of the orientation of a, b, c projected on the plane dropping axis k
/// (equal to the sign of the k-th component of (b − a) × (c − a)).
int orient2d_axis(const Point3& a, const Point3& b, const Point3& c, int k);

/// A coordinate plane where a, b, c project to a non-degenerate triangle.
struct PlaneAxis {
  int drop = 0;         ///< the dropped axis k
  int orientation = 0;  ///< sign of the projected orientation of a, b, c (±1)
};

/// \throws InvalidInput if a, b, c are collinear (`where` names the caller).
PlaneAxis choose_plane_axis(const Point3& a, const Point3& b, const Point3& c,
                            const char* where);

}  // namespace rstruct::predicates::detail
