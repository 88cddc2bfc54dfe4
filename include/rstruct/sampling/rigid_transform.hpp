#pragma once
/// \file
/// Rigid motions x ↦ Qx + t (Q a rotation) and a Surface moved by one. Everything a
/// surface knows moves with it: implicit function, normal, closest point, lfs and medial
/// points, parametrization (cell reaches grow by a bound on the transform's rounding, so
/// certificates stay valid; see TransformedSurface::cell_reach). Translations up to about
/// 1e6 (and beyond) keep working: results are then accurate to the rounding of
/// coordinates of that size (|t|·2⁻⁵², 2e-10 at 1e6), which the reaches include.

#include <array>
#include <memory>

#include "rstruct/sampling/random.hpp"
#include "rstruct/sampling/surface.hpp"

namespace rstruct::sampling {

struct RigidTransform {
  /// Row-major rotation matrix.
  std::array<double, 9> q{1, 0, 0, 0, 1, 0, 0, 0, 1};
  Vec3 t{};

  Vec3 rotate(const Vec3& v) const {
    return {q[0] * v.x + q[1] * v.y + q[2] * v.z, q[3] * v.x + q[4] * v.y + q[5] * v.z,
            q[6] * v.x + q[7] * v.y + q[8] * v.z};
  }
  Vec3 rotate_back(const Vec3& v) const {
    return {q[0] * v.x + q[3] * v.y + q[6] * v.z, q[1] * v.x + q[4] * v.y + q[7] * v.z,
            q[2] * v.x + q[5] * v.y + q[8] * v.z};
  }
  Point3 apply(const Point3& x) const { return rotate(x) + t; }
  Point3 apply_inverse(const Point3& x) const { return rotate_back(x - t); }

  static RigidTransform identity() { return {}; }
  static RigidTransform translation(const Vec3& t) {
    RigidTransform r;
    r.t = t;
    return r;
  }
  /// Rotation by the unit quaternion (w, x, y, z) (normalised here).
  /// \throws InvalidInput for a zero or non-finite quaternion.
  static RigidTransform from_quaternion(double w, double x, double y, double z);
  /// A rotation uniformly distributed on SO(3) (normalised Gaussian quaternion).
  static RigidTransform random_rotation(Random& random);

  /// max |QᵀQ − I| entry (rounding of Q; about 1e-16 for Q from a quaternion).
  double orthogonality_defect() const;
};

/// `base` moved by `transform`. The base surface is shared, not copied.
class TransformedSurface final : public Surface {
 public:
  /// \throws InvalidInput if base is null, the transform has a non-finite entry, a
  /// translation component beyond 1e15 (coordinates there keep less than one bit below
  /// 0.1), or Q is not a rotation to within 1e-12.
  TransformedSurface(std::shared_ptr<const Surface> base, RigidTransform transform);

  const Surface& base() const { return *base_; }
  const RigidTransform& transform() const { return transform_; }

  std::string name() const override;
  double value(const Point3& x) const override { return base_->value(transform_.apply_inverse(x)); }
  Vec3 gradient(const Point3& x) const override {
    return transform_.rotate(base_->gradient(transform_.apply_inverse(x)));
  }
  Point3 closest_point(const Point3& x) const override {
    return transform_.apply(base_->closest_point(transform_.apply_inverse(x)));
  }
  Box3 bounding_box() const override;

  bool has_known_lfs() const override { return base_->has_known_lfs(); }
  std::optional<Point3> nearest_inner_medial_point(const Point3& x) const override;
  std::optional<Point3> nearest_outer_medial_point(const Point3& x) const override;
  double lfs(const Point3& x) const override { return base_->lfs(transform_.apply_inverse(x)); }
  std::string medial_axis_description() const override;

  bool has_parametrization() const override { return base_->has_parametrization(); }
  int chart_count() const override { return base_->chart_count(); }
  ParamCell chart_domain(int chart) const override { return base_->chart_domain(chart); }
  Point3 point(int chart, double u, double v) const override {
    return transform_.apply(base_->point(chart, u, v));
  }
  double area_element(int chart, double u, double v) const override {
    return base_->area_element(chart, u, v);
  }
  double max_area_element(int chart) const override { return base_->max_area_element(chart); }
  /// The base reach plus twice the rounding bound `rounding_pad()`: once for the computed
  /// image of the cell centre, once for lfs() evaluated through apply_inverse().
  CellReach cell_reach(const ParamCell& cell) const override;
  double area() const override { return base_->area(); }
  double meshing_step() const override { return base_->meshing_step(); }

  /// Bound on |computed apply(p) − exact image of p| for p within the base's bounding box,
  /// and likewise for apply_inverse (includes Q's deviation from a rotation).
  double rounding_pad() const { return pad_; }

 private:
  std::shared_ptr<const Surface> base_;
  RigidTransform transform_;
  double pad_ = 0;
};

}  // namespace rstruct::sampling
