#pragma once
/// \file
/// Exact geometric predicates on double inputs: the only place in rstruct that looks at
/// coordinates to decide something. Each predicate is exact for every finite double
/// input (no overflow/underflow failure): a semi-static floating-point filter first,
/// an exact stage when the filter cannot decide, and, for the in-sphere and power tests,
/// a symbolic perturbation that never answers zero.
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
/// Symbolic perturbation: the *_sos variants take a distinct integer id per point
/// (its index in the input) and decide as if weight w_i were perturbed by ε^(n−id)
/// (smaller id = larger perturbation), following Devillers & Teillaud, "Perturbations for
/// Delaunay and weighted Delaunay 3D triangulations", CGTA 44 (2011). They never return
/// zero when their precondition holds. orient3d itself is never perturbed: four coplanar
/// points give zero, and the triangulation treats such a (flat) tetrahedron as never
/// created (its conflict tests only call power tests on non-flat cells; coplanar
/// hull-facet cases use the coplanar_* predicates).

#include <cstdint>

#include "rstruct/geometry/vec3.hpp"
#include "rstruct/predicates/sign.hpp"

namespace rstruct::predicates {

/// Orientation of four points. Exact; zero iff coplanar.
Sign orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d);

/// In-sphere test, unperturbed (may return zero when the five points are cospherical).
Sign insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
              const Point3& e);

/// Power test of e against the orthosphere of a, b, c, d; unperturbed.
Sign power_test(const WeightedPoint& a, const WeightedPoint& b, const WeightedPoint& c,
                const WeightedPoint& d, const WeightedPoint& e);

/// Perturbed in-sphere test (all weights zero).
/// \pre orient3d(a, b, c, d) != 0 and the ids are pairwise distinct. Never returns zero.
Sign insphere_sos(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                  const Point3& e, std::uint32_t ia, std::uint32_t ib, std::uint32_t ic,
                  std::uint32_t id, std::uint32_t ie);

/// Perturbed power test.
/// \pre orient3d(a.c, b.c, c.c, d.c) != 0 and the ids are pairwise distinct.
/// Never returns zero.
Sign power_test_sos(const WeightedPoint& a, const WeightedPoint& b, const WeightedPoint& c,
                    const WeightedPoint& d, const WeightedPoint& e, std::uint32_t ia,
                    std::uint32_t ib, std::uint32_t ic, std::uint32_t id, std::uint32_t ie);

/// Perturbed power test of e against the orthocircle of three coplanar weighted points,
/// inside their common plane: positive iff e is in conflict with the triangle abc of the
/// 2D regular triangulation of that plane. Used for hull facets coplanar with a new point.
/// \pre a, b, c not collinear; e coplanar with them; ids pairwise distinct.
/// Never returns zero.
Sign coplanar_power_test_sos(const WeightedPoint& a, const WeightedPoint& b,
                             const WeightedPoint& c, const WeightedPoint& e, std::uint32_t ia,
                             std::uint32_t ib, std::uint32_t ic, std::uint32_t ie);

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
