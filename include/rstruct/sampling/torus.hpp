#pragma once
/// \file
/// The ring torus around the z axis with major radius R and minor radius a, R > a > 0
/// (DESIGN.md §8): inner medial axis = the core circle {ρ = R, z = 0}, outer medial axis =
/// the z axis, so lfs(x) = min(dist(x, core circle), dist(x, z axis)); on the torus this is
/// min(a, distance to the axis), which equals a when R ≥ 2a. Parametrized by one chart
/// (θ, φ) ∈ [0, 2π]²: P = ((R + a cos φ) cos θ, (R + a cos φ) sin θ, a sin φ).

#include "rstruct/sampling/surface.hpp"

namespace rstruct::sampling {

class Torus final : public Surface {
 public:
  /// \throws InvalidInput unless R > a > 0, both finite.
  Torus(double major_radius, double minor_radius);

  double major_radius() const { return major_; }
  double minor_radius() const { return minor_; }

  std::string name() const override;
  /// Signed distance sqrt((ρ − R)² + z²) − a, ρ = sqrt(x² + y²).
  double value(const Point3& x) const override;
  Vec3 gradient(const Point3& x) const override;
  Point3 closest_point(const Point3& x) const override;
  Box3 bounding_box() const override;

  bool has_known_lfs() const override { return true; }
  std::optional<Point3> nearest_inner_medial_point(const Point3& x) const override;
  std::optional<Point3> nearest_outer_medial_point(const Point3& x) const override {
    return Point3{0, 0, x.z};
  }
  std::string medial_axis_description() const override;

  bool has_parametrization() const override { return true; }
  int chart_count() const override { return 1; }
  ParamCell chart_domain(int chart) const override;
  Point3 point(int chart, double u, double v) const override;
  double area_element(int chart, double u, double v) const override;
  double max_area_element(int chart) const override;
  CellReach cell_reach(const ParamCell& cell) const override;
  /// 4π² R a.
  double area() const override;

 private:
  /// The point of the core circle nearest to x (any, if x is on the z axis).
  Point3 core_point(const Point3& x) const;
  double major_;
  double minor_;
};

/// Largest value of cos over [lo, hi].
double max_cos_over(double lo, double hi);

}  // namespace rstruct::sampling
