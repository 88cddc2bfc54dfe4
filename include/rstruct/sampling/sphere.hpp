#pragma once
/// \file
/// The sphere of radius R centred at the origin (DESIGN.md §8): medial axis = the centre,
/// lfs ≡ R on the sphere. Parametrized by the six faces of the cube (no poles), see
/// cube_sphere.hpp.

#include "rstruct/sampling/surface.hpp"

namespace rstruct::sampling {

class Sphere final : public Surface {
 public:
  /// \throws InvalidInput unless radius is finite and > 0.
  explicit Sphere(double radius);

  double radius() const { return radius_; }

  std::string name() const override;
  /// Signed distance |x| − R.
  double value(const Point3& x) const override { return norm(x) - radius_; }
  Vec3 gradient(const Point3& x) const override;
  Point3 closest_point(const Point3& x) const override;
  Box3 bounding_box() const override;

  bool has_known_lfs() const override { return true; }
  std::optional<Point3> nearest_inner_medial_point(const Point3&) const override {
    return Point3{0, 0, 0};
  }
  std::string medial_axis_description() const override;

  bool has_parametrization() const override { return true; }
  int chart_count() const override { return 6; }
  ParamCell chart_domain(int chart) const override;
  Point3 point(int chart, double u, double v) const override;
  double area_element(int chart, double u, double v) const override;
  double max_area_element(int chart) const override;
  CellReach cell_reach(const ParamCell& cell) const override;
  /// 4πR².
  double area() const override;

 private:
  double radius_;
};

}  // namespace rstruct::sampling
