#pragma once
/// \file
/// The exact stage: the polynomials of polynomials.hpp evaluated in GMP integers on
/// exactly scaled inputs (scaled_integer.hpp). Each function returns the sign (−1, 0, +1)
/// of the same quantity as the filter of the same name, for every finite input, and
/// throws rstruct::InvalidInput on a NaN or infinite input.

#include <initializer_list>

#include "rstruct/geometry/vec3.hpp"

namespace rstruct::predicates::detail {

int orient3d_exact(const Point3& a, const Point3& b, const Point3& c, const Point3& d);
int orient2d_exact(const Point3& a, const Point3& b, const Point3& c, int k);
/// Sign of −det[(p − e, |p − e|² − (w_p − w_e))], p = a, b, c, d.
int lifted4_exact(const WeightedPoint& a, const WeightedPoint& b, const WeightedPoint& c,
                  const WeightedPoint& d, const WeightedPoint& e);
int coplanar_power_exact(const WeightedPoint& a, const WeightedPoint& b,
                         const WeightedPoint& c, const WeightedPoint& e, int k);
int collinear_power_exact(const WeightedPoint& a, const WeightedPoint& b,
                          const WeightedPoint& e, int k);
int squared_distance_difference_exact(const Point3& x, const Point3& p, const Point3& q);
int power_difference_exact(const Point3& x, const WeightedPoint& p, const WeightedPoint& q);
int power_value_exact(const Point3& x, const WeightedPoint& p);
int ball_side_exact(const Point3& x, const Point3& centre, double r);

/// Throws InvalidInput naming `where` unless every value is finite.
void require_finite(const char* where, std::initializer_list<double> values);

}  // namespace rstruct::predicates::detail
