#pragma once
// Which side of a plane the circumcentre of a tetrahedron lies on, decided exactly.
//
// The medial axis keeps a Voronoi vertex of V only if it lies in the normal cones of its
// four sites, and clips Voronoi faces by the planes of those cones. The vertex is the
// circumcentre of a Delaunay cell of V, and near-degenerate unions (four spheres almost
// through one point, split into clusters of boundary vertices 10⁻⁶ … 10⁻¹⁴ apart) make that
// cell a needle whose rounded circumcentre is off by far more than its distance to a cone
// face. So the side is decided on the cell's own points, never on the rounded centre.

#include <array>
#include <cstdint>

#include "complex/filtered_number.hpp"
#include "rstruct/geometry/vec3.hpp"
#include "rstruct/predicates/sign.hpp"

namespace rstruct::medial {

/// The sign of orient3d(s, p, q, z) where z is the circumcentre of a, b, c, d, evaluated
/// exactly on the double inputs (a certified floating-point filter, then GMP rationals):
///   orient3d(s, p, q, z) = n·(z − s), n = (p − s) × (q − s), and
///   z − a = v / (2Δ), Δ = det[u₁; u₂; u₃], v = |u₁|² u₂×u₃ + |u₂|² u₃×u₁ + |u₃|² u₁×u₂,
///   u₁ = b − a, u₂ = c − a, u₃ = d − a,
/// so the sign is that of (2Δ n·(a − s) + n·v) times the sign of Δ.
/// \pre a, b, c, d are affinely independent (a finite cell of a triangulation).
Sign circumcentre_side(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                       const Point3& s, const Point3& p, const Point3& q);

/// The sign of n·(z − o), n = (e1_to − e1_from) × (e2_to − e2_from), z the circumcentre of
/// a, b, c, d (the form above is o = s, e1 = s→p, e2 = s→q). Exact, as above.
Sign circumcentre_side(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                       const Point3& o, const Point3& e1_from, const Point3& e1_to,
                       const Point3& e2_from, const Point3& e2_to);

/// The sign of (z − p)·w, z the circumcentre of a, b, c, d and w the component of s − p
/// perpendicular to the line pq: positive iff z lies on s's side of the plane through the
/// line pq perpendicular to s's direction from it. Exact, as above.
Sign circumcentre_radial_side(const Point3& a, const Point3& b, const Point3& c,
                              const Point3& d, const Point3& s, const Point3& p,
                              const Point3& q);

/// The sign of n·(z − o) for an input point z, n as above. Exact.
Sign point_side(const Point3& z, const Point3& o, const Point3& e1_from, const Point3& e1_to,
                const Point3& e2_from, const Point3& e2_to);

/// The same predicates for many planes against one cell: the plane-independent terms of
/// the filter stage (v and Δ) are computed once.
class CellCircumcentre {
 public:
  CellCircumcentre() = default;
  CellCircumcentre(const Point3& a, const Point3& b, const Point3& c, const Point3& d);

  /// circumcentre_side(a, b, c, d, o, e1_from, e1_to, e2_from, e2_to).
  Sign side(const Point3& o, const Point3& e1_from, const Point3& e1_to, const Point3& e2_from,
            const Point3& e2_to) const;
  /// circumcentre_side(a, b, c, d, s, p, q).
  Sign side(const Point3& s, const Point3& p, const Point3& q) const {
    return side(s, s, p, s, q);
  }
  /// circumcentre_radial_side(a, b, c, d, s, p, q).
  Sign radial_side(const Point3& s, const Point3& p, const Point3& q) const;

 private:
  std::array<Point3, 4> point_{};
  std::array<complex::detail::FilteredNumber, 3> v_{};
  complex::detail::FilteredNumber delta_{};
};

/// Calls that the floating-point filter could not decide (for tests and reports).
std::uint64_t circumcentre_side_exact_calls();

}  // namespace rstruct::medial
