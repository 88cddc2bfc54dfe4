#include "rstruct/sampling/rigid_transform.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "rstruct/core/error.hpp"

namespace rstruct::sampling {

RigidTransform RigidTransform::from_quaternion(double w, double x, double y, double z) {
  const double n = std::sqrt(w * w + x * x + y * y + z * z);
  if (!std::isfinite(n) || n == 0.0) {
    throw InvalidInput("rotation: quaternion must be finite and non-zero");
  }
  w /= n;
  x /= n;
  y /= n;
  z /= n;
  RigidTransform r;
  r.q = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
         2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
         2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
  return r;
}

RigidTransform RigidTransform::random_rotation(Random& random) {
  // A standard Gaussian in R⁴ normalised is uniform on S³, and unit quaternions map onto
  // SO(3) two-to-one with the Haar measure as image.
  for (;;) {
    const double w = random.normal(), x = random.normal(), y = random.normal(), z = random.normal();
    if (w * w + x * x + y * y + z * z > 1e-6) return from_quaternion(w, x, y, z);
  }
}

double RigidTransform::orthogonality_defect() const {
  double worst = 0.0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      double s = 0.0;
      for (int k = 0; k < 3; ++k)
        s += q[static_cast<std::size_t>(3 * k + i)] * q[static_cast<std::size_t>(3 * k + j)];
      worst = std::max(worst, std::fabs(s - (i == j ? 1.0 : 0.0)));
    }
  }
  return worst;
}

TransformedSurface::TransformedSurface(std::shared_ptr<const Surface> base,
                                       RigidTransform transform)
    : base_(std::move(base)), transform_(transform) {
  if (!base_) throw InvalidInput("transformed surface: no base surface");
  for (double v : transform_.q) {
    if (!std::isfinite(v)) throw InvalidInput("transformed surface: non-finite rotation");
  }
  if (!is_finite(transform_.t)) throw InvalidInput("transformed surface: non-finite translation");
  for (std::size_t i = 0; i < 3; ++i) {
    if (std::fabs(transform_.t[i]) > 1e15) {
      throw InvalidInput("transformed surface: translation components must be at most 1e15");
    }
  }
  const double defect = transform_.orthogonality_defect();
  if (defect > 1e-12) {
    std::ostringstream msg;
    msg << "transformed surface: matrix is not a rotation (|QᵀQ − I| = " << defect << ")";
    throw InvalidInput(msg.str());
  }
  const Box3 box = base_->bounding_box();
  const double extent = std::max(norm(box.lo), norm(box.hi));
  const double tmax =
      std::max({std::fabs(transform_.t.x), std::fabs(transform_.t.y), std::fabs(transform_.t.z)});
  // Each coordinate of Qp + t takes 5 roundings, each ≤ 2⁻⁵³ of a quantity ≤ |p| + |t|;
  // Q's deviation from the nearest rotation moves points by ≤ 3·defect·|p|. The inverse
  // map is bounded the same way with |x| ≤ |p| + |t|. 2⁻⁴⁸ is a generous multiple.
  pad_ = 0x1.0p-48 * (2.0 * extent + 2.0 * std::sqrt(3.0) * tmax) +
         3.0 * (defect + 0x1.0p-50) * extent;
}

std::string TransformedSurface::name() const {
  std::ostringstream out;
  out << base_->name() << " moved by a rigid transform";
  return out.str();
}

Box3 TransformedSurface::bounding_box() const {
  const Box3 b = base_->bounding_box();
  Box3 out;
  for (int c = 0; c < 8; ++c) {
    out.add(transform_.apply(
        {(c & 1) ? b.hi.x : b.lo.x, (c & 2) ? b.hi.y : b.lo.y, (c & 4) ? b.hi.z : b.lo.z}));
  }
  const Vec3 pad{pad_, pad_, pad_};
  out.lo -= pad;
  out.hi += pad;
  return out;
}

std::optional<Point3> TransformedSurface::nearest_inner_medial_point(const Point3& x) const {
  const auto m = base_->nearest_inner_medial_point(transform_.apply_inverse(x));
  if (!m) return std::nullopt;
  return transform_.apply(*m);
}

std::optional<Point3> TransformedSurface::nearest_outer_medial_point(const Point3& x) const {
  const auto m = base_->nearest_outer_medial_point(transform_.apply_inverse(x));
  if (!m) return std::nullopt;
  return transform_.apply(*m);
}

std::string TransformedSurface::medial_axis_description() const {
  return base_->medial_axis_description() + " (moved by the same rigid transform)";
}

CellReach TransformedSurface::cell_reach(const ParamCell& cell) const {
  CellReach r = base_->cell_reach(cell);
  r.u_reach += 2.0 * pad_;
  return r;
}

}  // namespace rstruct::sampling
