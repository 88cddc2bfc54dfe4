#pragma once
/// \file
/// A certified one-sided test: two balls are disjoint. The dual complex uses it as a
/// shortcut of its orthosphere predicates (orthosphere_predicates.hpp): if two balls of a
/// simplex σ are disjoint, no point lies in all of σ's balls, so the centre z_σ of σ's
/// smallest orthosphere has positive power to one of them, hence (equal powers) to all:
/// orthosphere_power_sign(σ) is positive and σ is not in K. The same holds for every
/// simplex containing the pair. The test answers "disjoint" only when the floating-point
/// evaluation proves it (error analysis below); otherwise the caller asks the exact
/// predicates, so the complex is the same with or without it.

#include <cmath>
#include <limits>

#include "rstruct/geometry/vec3.hpp"

namespace rstruct::complex {

/// An upper bound of √w, the radius of a ball of weight w (sqrt is correctly rounded, the
/// next double up bounds it); NaN when w is negative or NaN (an imaginary ball: the test
/// below then never answers "disjoint").
inline double radius_upper_bound(double w) {
  if (!(w >= 0)) return std::numeric_limits<double>::quiet_NaN();
  return std::nextafter(std::sqrt(w), std::numeric_limits<double>::infinity());
}

/// True only if the balls (a, ra) and (b, rb) are disjoint (|a − b| > ra + rb, not even
/// touching), where ra and rb are radius_upper_bound of the true radii. False means
/// "not proven": the balls may still be disjoint.
///
/// Why it is certified (u = 2⁻⁵³, no FMA contraction, see meson.build): the computed
/// d² = Σ fl(a_i − b_i)² is within a factor (1 ± 7u) of |a − b|², and the computed s² of
/// s = fl(ra + rb) bounds (ra + rb)² from above within (1 + u)³; underflow adds at most a
/// few 2⁻¹⁰⁷⁴ absolute, negligible once d² ≥ 2⁻⁹⁰⁰. The margins 1 ∓ 2⁻⁴⁰ (also rounded)
/// dwarf these factors, so the comparison implies |a − b|² > (ra + rb)². The upper limit
/// on d² keeps every product finite; NaN radii make the comparison false.
inline bool balls_certainly_disjoint(const Point3& a, double ra, const Point3& b, double rb) {
  const double dx = a[0] - b[0];
  const double dy = a[1] - b[1];
  const double dz = a[2] - b[2];
  const double d2 = dx * dx + dy * dy + dz * dz;
  const double s = ra + rb;
  constexpr double kLow = 1 - 0x1p-40;
  constexpr double kHigh = 1 + 0x1p-40;
  return d2 >= 0x1p-900 && d2 <= 0x1p+1000 && d2 * kLow > s * s * kHigh;
}

}  // namespace rstruct::complex
