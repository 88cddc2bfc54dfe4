#pragma once
/// \file
/// Closest points on ellipses and ellipsoids, and on filled ellipses (the medial axis of
/// an ellipsoid, DESIGN.md §8), computed to full double precision by bisection.
///
/// Method (derived from the Lagrange condition, written for this project): for an
/// ellipsoid Σ (x_i/e_i)² = 1 with e_0 ≥ … ≥ e_{n−1} > 0 and a query y with y_i ≥ 0, the
/// closest point is x_i = e_i² y_i / (s + e_i² − e_{n−1}²) where s > 0 is the unique root
/// of the strictly decreasing F(s) = Σ (e_i y_i / (s + e_i² − e_{n−1}²))² − 1, bracketed by
/// s ∈ [e_{n−1} y_{n−1}, |(e_i y_i)_i|]. When y_{n−1} = 0 either the query projects into
/// the interior of the "focal" region (then x_{n−1} ≠ 0 and s = 0) or x_{n−1} = 0 and the
/// problem drops one dimension. F is convex, so Newton's method started at the lower end
/// of the bracket increases monotonically to the root; it runs until it stops increasing
/// (bisection takes over if rounding ever pushes an iterate out of the bracket), so s is
/// found to within a few units in the last place; the resulting distance is accurate to
/// about 1e-15 relative (tests check 1e-12 against brute force and bisection).

#include <array>

namespace rstruct::sampling {

/// Closest point of the ellipsoid with semi-axes `axes` (any order, all > 0, along the
/// coordinate axes) to `y`. For points on the medial axis several points are closest;
/// one of them is returned.
std::array<double, 3> closest_point_on_ellipsoid(const std::array<double, 3>& axes,
                                                 const std::array<double, 3>& y);

/// Closest point of the filled ellipse {(x, y) : (x/alpha)² + (y/beta)² ≤ 1} to (p, q),
/// alpha ≥ beta ≥ 0 (beta = 0: the segment [−alpha, alpha] × {0}; alpha = 0: the origin).
std::array<double, 2> closest_point_on_filled_ellipse(double alpha, double beta, double p,
                                                      double q);

}  // namespace rstruct::sampling
