#pragma once
/// \file
/// Exact geometric predicates on double inputs: the only place in rstruct that looks at
/// coordinates to decide something. Each predicate is exact for every finite double
/// input (no overflow/underflow failure): a semi-static floating-point filter first, for
/// the in-sphere and power tests a dynamic filter next (detail/dynamic_filter.hpp), an exact
/// stage when the filters cannot decide, and, for the in-sphere and power tests, a symbolic
/// perturbation that never answers zero.
///
/// Conventions (all predicates):
///  - orient3d(a, b, c, d) is the sign of det[b − a; c − a; d − a] (rows): positive iff d
///    lies on the side of plane abc into which (b − a) × (c − a) points. A tetrahedron
///    (a, b, c, d) is *positively oriented* iff orient3d(a, b, c, d) > 0.
///  - insphere(a, b, c, d, e) is positive iff e lies strictly inside the sphere through
///    a, b, c, d when (a, b, c, d) is positively oriented; the sign flips with the
///    orientation (it is the sign of the lifted 5×5 determinant times a fixed constant).
///  - power_test(a, b, c, d, e) on weighted points (c, w): the same determinant with lifting
///    heights |c|² − w. Positive iff the power of e against the orthosphere of a, b, c, d
///    is negative (e is "in conflict": e's power cell would cut the cell), for positively
///    oriented a, b, c, d. With all weights zero it equals insphere.
///
/// Symbolic perturbation (Devillers & Teillaud, "Perturbations for Delaunay and weighted
/// Delaunay 3D triangulations", CGTA 44 (2011), weight perturbation): the *_sos variants
/// take a distinct integer id per point (its index in the input) and decide as if every
/// weight w_i were replaced by w_i + ε^(id_i + 1) for an infinitesimal ε > 0 (so a smaller
/// id means a larger perturbation). This is one global perturbation of the input, so all
/// perturbed answers are mutually consistent (they are the exact answers for the perturbed
/// input). The lifted determinant is linear in each lifting height, hence the perturbed
/// sign is: the unperturbed sign if non-zero, else the sign of the cofactor of the point
/// with the smallest id among those whose cofactor (an orientation of the other points)
/// is non-zero. The cofactor of the query point e is the orientation of the cell, non-zero
/// by precondition, so the perturbed predicates never return zero. For Delaunay (all
/// weights zero) no point of a set of distinct points becomes hidden under it.
///
/// Coplanar points: orient3d itself is never perturbed; four coplanar points give zero.
/// The triangulation never creates a flat cell (its conflict tests call the 3D power tests
/// only on cells with orient3d > 0). A new point e coplanar with a hull facet abc (the
/// infinite cell abc∞) is in conflict with that infinite cell iff coplanar_power_test_sos
/// (a, b, c, e) > 0: the in-plane power test of the same perturbed input, which is the
/// limit of the 3D test as the fourth point goes to infinity off the plane. In dimension
/// 1 (all points so far collinear) collinear_power_test_sos plays the same role.
///
/// Precondition of every predicate: finite coordinates and weights. A NaN or infinity
/// throws rstruct::InvalidInput (checked on the slow path only, so a filter that decides
/// never looks). Counters of how often each stage decides: predicates/counters.hpp.
///
/// orient3d, insphere, power_test and their _sos variants are inline: the filter (the
/// common case) runs in the caller, the exact and perturbation stages are out of line
/// (detail::*_after_filter), as in Geogram and CGAL.

#include <cstdint>

#include "rstruct/geometry/vec3.hpp"
#include "rstruct/predicates/detail/counting.hpp"
#include "rstruct/predicates/detail/filters.hpp"
#include "rstruct/predicates/sign.hpp"

namespace rstruct::predicates {

namespace detail {
/// The stages after the filter (for the in-sphere and power tests a dynamic filter, see
/// detail/dynamic_filter.hpp; then exact, then perturbation), out of line; each counts the
/// stage that decides. \pre the filter of the same predicate returned kUndecided.
Sign orient3d_after_filter(const Point3& a, const Point3& b, const Point3& c,
                          const Point3& d);
Sign insphere_after_filter(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                           const Point3& e);
Sign power_test_after_filter(const WeightedPoint& a, const WeightedPoint& b,
                             const WeightedPoint& c, const WeightedPoint& d,
                             const WeightedPoint& e);
Sign insphere_sos_after_filter(const Point3& a, const Point3& b, const Point3& c,
                               const Point3& d, const Point3& e, std::uint32_t ia,
                               std::uint32_t ib, std::uint32_t ic, std::uint32_t id,
                               std::uint32_t ie);
Sign power_test_sos_after_filter(const WeightedPoint& a, const WeightedPoint& b,
                                 const WeightedPoint& c, const WeightedPoint& d,
                                 const WeightedPoint& e, std::uint32_t ia, std::uint32_t ib,
                                 std::uint32_t ic, std::uint32_t id, std::uint32_t ie);
}  // namespace detail

/// Orientation of four points. Exact; zero iff coplanar.
inline Sign orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const int f = detail::orient3d_filter(a, b, c, d);
  if (f != detail::kUndecided) [[likely]] {
    RSTRUCT_PREDICATE_COUNT(orient3d, filter);
    return static_cast<Sign>(f);
  }
  return detail::orient3d_after_filter(a, b, c, d);
}

/// In-sphere test, unperturbed (may return zero when the five points are cospherical).
inline Sign insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                     const Point3& e) {
  const int f = detail::insphere_filter(a, b, c, d, e);
  if (f != detail::kUndecided) [[likely]] {
    RSTRUCT_PREDICATE_COUNT(insphere, filter);
    return static_cast<Sign>(f);
  }
  return detail::insphere_after_filter(a, b, c, d, e);
}

/// Power test of e against the orthosphere of a, b, c, d; unperturbed.
inline Sign power_test(const WeightedPoint& a, const WeightedPoint& b, const WeightedPoint& c,
                       const WeightedPoint& d, const WeightedPoint& e) {
  const int f = detail::lifted4_filter<true>(a, b, c, d, e);
  if (f != detail::kUndecided) [[likely]] {
    RSTRUCT_PREDICATE_COUNT(power_test, filter);
    return static_cast<Sign>(f);
  }
  return detail::power_test_after_filter(a, b, c, d, e);
}

/// Perturbed in-sphere test (all weights zero).
/// \pre orient3d(a, b, c, d) != 0 and the ids are pairwise distinct. Never returns zero.
inline Sign insphere_sos(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                         const Point3& e, std::uint32_t ia, std::uint32_t ib, std::uint32_t ic,
                         std::uint32_t id, std::uint32_t ie) {
  const int f = detail::insphere_filter(a, b, c, d, e);
  if (f != detail::kUndecided) [[likely]] {
    RSTRUCT_PREDICATE_COUNT(insphere, filter);
    return static_cast<Sign>(f);
  }
  return detail::insphere_sos_after_filter(a, b, c, d, e, ia, ib, ic, id, ie);
}

/// Perturbed power test.
/// \pre orient3d(a.c, b.c, c.c, d.c) != 0 and the ids are pairwise distinct.
/// Never returns zero.
inline Sign power_test_sos(const WeightedPoint& a, const WeightedPoint& b,
                           const WeightedPoint& c, const WeightedPoint& d,
                           const WeightedPoint& e, std::uint32_t ia, std::uint32_t ib,
                           std::uint32_t ic, std::uint32_t id, std::uint32_t ie) {
  const int f = detail::lifted4_filter<true>(a, b, c, d, e);
  if (f != detail::kUndecided) [[likely]] {
    RSTRUCT_PREDICATE_COUNT(power_test, filter);
    return static_cast<Sign>(f);
  }
  return detail::power_test_sos_after_filter(a, b, c, d, e, ia, ib, ic, id, ie);
}

/// Perturbed power test of e against the orthocircle of three coplanar weighted points,
/// inside their common plane: positive iff e is in conflict with the triangle abc of the
/// 2D regular triangulation of that plane. Used for hull facets coplanar with a new point.
/// \pre a, b, c not collinear; e coplanar with them; ids pairwise distinct.
/// Never returns zero.
Sign coplanar_power_test_sos(const WeightedPoint& a, const WeightedPoint& b,
                             const WeightedPoint& c, const WeightedPoint& e, std::uint32_t ia,
                             std::uint32_t ib, std::uint32_t ic, std::uint32_t ie);

/// Orientation of d against the plane through a, b, c seen inside that plane, for four
/// coplanar points: positive iff d lies on the same side of line ab as c, zero iff d is on
/// line ab, negative otherwise. Independent of any projection. Exact.
/// \pre a, b, c not collinear; d coplanar with a, b, c.
Sign coplanar_orientation(const Point3& a, const Point3& b, const Point3& c, const Point3& d);

/// Unperturbed in-plane power test of e against the orthocircle of a, b, c (coplanar):
/// the sign of −π(e), π(e) = |e − z|² − W − w_e the power of e against the orthocircle
/// (z, W): positive iff e is in conflict with triangle abc of the plane's 2D regular
/// triangulation, zero iff e is orthogonal to the orthocircle. Exact.
/// \pre a, b, c not collinear; e coplanar with them.
Sign coplanar_power_test(const WeightedPoint& a, const WeightedPoint& b,
                         const WeightedPoint& c, const WeightedPoint& e);

/// Unperturbed power test of e against the "orthosegment" of two weighted points a, b on a
/// line through e: positive iff the power of e against every sphere orthogonal to a and
/// b is negative (e in conflict with the edge ab of the 1D regular triangulation). Exact.
/// \pre a.c != b.c; e collinear with a, b.
Sign collinear_power_test(const WeightedPoint& a, const WeightedPoint& b,
                          const WeightedPoint& e);

/// Perturbed collinear_power_test (same perturbation as power_test_sos).
/// \pre as collinear_power_test; ids pairwise distinct. Never returns zero.
Sign collinear_power_test_sos(const WeightedPoint& a, const WeightedPoint& b,
                              const WeightedPoint& e, std::uint32_t ia, std::uint32_t ib,
                              std::uint32_t ie);

/// Perturbed comparison of the powers of two weighted points at the same location (the
/// zero-dimensional power test): positive iff e hides a, i.e. w_e + ε^(ie+1) >
/// w_a + ε^(ia+1). \pre a.c == e.c, ia != ie. Never returns zero.
Sign coincident_power_test_sos(const WeightedPoint& a, const WeightedPoint& e,
                               std::uint32_t ia, std::uint32_t ie);

/// Sign of |x − p|² − |x − q|² (which of p, q is nearer to x). Exact.
Sign compare_squared_distance(const Point3& x, const Point3& p, const Point3& q);

/// Sign of π_p(x) − π_q(x) = (|x − p.c|² − p.w) − (|x − q.c|² − q.w). Exact.
Sign compare_power_distance(const Point3& x, const WeightedPoint& p, const WeightedPoint& q);

/// Sign of the power |x − p.c|² − p.w of x against weighted point p: negative inside the
/// ball, zero on its sphere, positive outside. Exact.
Sign power_sign(const Point3& x, const WeightedPoint& p);

/// Side of x against the ball B(c, r), r a double radius (r² taken exactly):
/// negative inside, zero on the sphere, positive outside. Exact.
Sign side_of_ball(const Point3& x, const Point3& c, double r);

}  // namespace rstruct::predicates
