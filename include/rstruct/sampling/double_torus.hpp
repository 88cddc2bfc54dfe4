#pragma once
/// \file
/// A smooth genus-2 "double torus" (the shape of the paper's Figure 11: a big ring and a
/// small ring joined side by side). Implicit function: the smooth minimum
///   f = −k ln(exp(−d₁/k) + exp(−d₂/k))
/// of the signed distances d_i = sqrt((ρ_i − R_i)² + z²) − a_i of two ring tori around
/// vertical axes through (c_i, 0, 0). f is C^∞ wherever both d_i are (off the tori's axes
/// and core circles, which stay far from the zero set for the default parameters), and
/// |∇f| > 0 on the zero set (∇f is a convex combination of two unit vectors that are never
/// opposite there; tests check min |∇f| over a fine mesh). Defaults: big ring R₁ = 1,
/// a₁ = 0.35 at the origin, small ring R₂ = 0.45, a₂ = 0.18 centred at x = 1.7, blend
/// k = 0.04: the tubes overlap near x ≈ 1.2 and both holes stay open, so the genus is 2
/// (tests check it through the Euler characteristic of a marching-tetrahedra mesh).
/// The local feature size of this surface is not known in closed form: has_known_lfs()
/// is false and only uniform (--n) sampling applies.
/// closest_point(): Newton projection onto f = 0 followed by tangential correction steps
/// until x − y is parallel to ∇f; this is the closest point for queries closer to F than
/// its reach (and a local critical point of the distance otherwise).

#include <memory>
#include <mutex>

#include "rstruct/sampling/surface.hpp"

namespace rstruct::sampling {

struct DoubleTorusParameters {
  double big_major = 1.0, big_minor = 0.35;
  double small_major = 0.45, small_minor = 0.18;
  double small_centre_x = 1.7;
  double blend = 0.04;
};

class DoubleTorus final : public Surface {
 public:
  /// \throws InvalidInput on non-finite or non-positive radii, R_i ≤ a_i, or blend ≤ 0.
  explicit DoubleTorus(DoubleTorusParameters parameters = {});

  const DoubleTorusParameters& parameters() const { return p_; }

  std::string name() const override;
  double value(const Point3& x) const override;
  Vec3 gradient(const Point3& x) const override;
  Point3 closest_point(const Point3& x) const override;
  Box3 bounding_box() const override;
  /// Projects x onto f = 0 along the gradient (Newton's method); not the closest point in
  /// general, but within O(f²) of it.
  Point3 project(const Point3& x) const;
  /// min(a₁, a₂) / 12.
  double meshing_step() const override;
  /// Area of a marching-tetrahedra mesh with grid step min(a₁, a₂)/12 whose vertices are
  /// projected onto F (relative error O(h²κ²), about 1e-3), computed once.
  double area() const override;

 private:
  /// Signed distance to torus i and its gradient.
  double torus_distance(int i, const Point3& x, Vec3* gradient) const;
  DoubleTorusParameters p_;
  mutable std::once_flag area_once_;
  mutable double area_ = 0;
};

}  // namespace rstruct::sampling
