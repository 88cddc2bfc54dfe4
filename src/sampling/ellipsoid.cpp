#include "rstruct/sampling/ellipsoid.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "rstruct/core/error.hpp"
#include "rstruct/sampling/cube_sphere.hpp"
#include "rstruct/sampling/ellipse_projection.hpp"

namespace rstruct::sampling {

Ellipsoid::Ellipsoid(double a, double b, double c) : axes_{a, b, c} {
  for (double e : axes_) {
    if (!is_supported_length(e)) {
      std::ostringstream msg;
      msg << "ellipsoid: semi-axes must be in [" << kMinLength << ", " << kMaxLength << "], got "
          << a << ", " << b << ", " << c;
      throw InvalidInput(msg.str());
    }
  }
  order_ = {0, 1, 2};
  std::stable_sort(order_.begin(), order_.end(), [&](int i, int j) {
    return axes_[static_cast<std::size_t>(i)] > axes_[static_cast<std::size_t>(j)];
  });
  const double e0 = axes_[static_cast<std::size_t>(order_[0])];
  const double e1 = axes_[static_cast<std::size_t>(order_[1])];
  const double e2 = axes_[static_cast<std::size_t>(order_[2])];
  alpha_ = (e0 - e2) * (e0 + e2) / e0;
  beta_ = (e1 - e2) * (e1 + e2) / e1;
  max_axis_ = e0;
}

std::string Ellipsoid::name() const {
  std::ostringstream out;
  out << "ellipsoid(a=" << axes_[0] << ", b=" << axes_[1] << ", c=" << axes_[2] << ")";
  return out.str();
}

double Ellipsoid::value(const Point3& x) const {
  double s = -1.0;
  for (std::size_t i = 0; i < 3; ++i) s += (x[i] / axes_[i]) * (x[i] / axes_[i]);
  return s;
}

Vec3 Ellipsoid::gradient(const Point3& x) const {
  Vec3 g;
  for (std::size_t i = 0; i < 3; ++i) g[i] = 2.0 * x[i] / (axes_[i] * axes_[i]);
  return g;
}

Point3 Ellipsoid::closest_point(const Point3& x) const {
  const auto p = closest_point_on_ellipsoid(axes_, {x.x, x.y, x.z});
  return {p[0], p[1], p[2]};
}

Box3 Ellipsoid::bounding_box() const {
  return {{-axes_[0], -axes_[1], -axes_[2]}, {axes_[0], axes_[1], axes_[2]}};
}

std::optional<Point3> Ellipsoid::nearest_inner_medial_point(const Point3& x) const {
  const auto i0 = static_cast<std::size_t>(order_[0]);
  const auto i1 = static_cast<std::size_t>(order_[1]);
  const auto m = closest_point_on_filled_ellipse(alpha_, beta_, x[i0], x[i1]);
  Point3 result{0, 0, 0};
  result[i0] = m[0];
  result[i1] = m[1];
  return result;
}

std::string Ellipsoid::medial_axis_description() const {
  std::ostringstream out;
  const char* names = "xyz";
  out << "inner only: the filled ellipse with semi-axis " << alpha_ << " along " << names[order_[0]]
      << " and " << beta_ << " along " << names[order_[1]] << " in the plane " << names[order_[2]]
      << " = 0";
  return out.str();
}

ParamCell Ellipsoid::chart_domain(int chart) const { return {chart, -1.0, 1.0, -1.0, 1.0}; }

Point3 Ellipsoid::point(int chart, double u, double v) const {
  const Vec3 s = cube_sphere_point(chart, u, v);
  return {axes_[0] * s.x, axes_[1] * s.y, axes_[2] * s.z};
}

double Ellipsoid::area_element(int chart, double u, double v) const {
  // For P = D s with D = diag(a, b, c): P_u × P_v = det(D) D⁻¹ (s_u × s_v) and
  // s_u × s_v = s · |s_u × s_v|, so |P_u × P_v| = abc |D⁻¹ s| |s_u × s_v|.
  const Vec3 s = cube_sphere_point(chart, u, v);
  const Vec3 ds{s.x / axes_[0], s.y / axes_[1], s.z / axes_[2]};
  return axes_[0] * axes_[1] * axes_[2] * norm(ds) * cube_sphere_area_element(u, v);
}

double Ellipsoid::max_area_element(int) const {
  // |D⁻¹ s| ≤ 1 / min axis and |s_u × s_v| ≤ 1.
  const double emin = std::min({axes_[0], axes_[1], axes_[2]});
  return axes_[0] * axes_[1] * axes_[2] / emin;
}

CellReach Ellipsoid::cell_reach(const ParamCell& cell) const {
  // Two bounds on |P_u| = |D s_u|, the smaller is used:
  //  (1) |D s_u| ≤ max axis · |s_u| (cube_sphere_speed_bounds);
  //  (2) s_u = e_u/|w| − w u/|w|³, so |D s_u| ≤ e_u-axis/|w| + |u| |D w| / |w|³, with |w|
  //      minimal and |u|, |D w| maximal over the cell. Likewise for v.
  const CubeSphereSpeeds s = cube_sphere_speed_bounds(cell);
  const int axis = cell.chart / 2;
  const double e0 = axes_[static_cast<std::size_t>(axis)];
  const double e1 = axes_[static_cast<std::size_t>((axis + 1) % 3)];
  const double e2 = axes_[static_cast<std::size_t>((axis + 2) % 3)];
  const double umin = min_abs_over(cell.u0, cell.u1), umax = max_abs_over(cell.u0, cell.u1);
  const double vmin = min_abs_over(cell.v0, cell.v1), vmax = max_abs_over(cell.v0, cell.v1);
  const double wmin = std::sqrt(1.0 + umin * umin + vmin * vmin);
  const double dw_max = std::sqrt(e0 * e0 + e1 * e1 * umax * umax + e2 * e2 * vmax * vmax);
  const double w3 = wmin * wmin * wmin;
  const double speed_u = std::min(max_axis_ * s.su, e1 / wmin + umax * dw_max / w3);
  const double speed_v = std::min(max_axis_ * s.sv, e2 / wmin + vmax * dw_max / w3);
  const double pad = 2.0 * kPointRounding * max_axis_;
  return {speed_u * 0.5 * (cell.u1 - cell.u0) + pad, speed_v * 0.5 * (cell.v1 - cell.v0)};
}

double Ellipsoid::area() const {
  const double a = axes_[static_cast<std::size_t>(order_[0])];
  const double b = axes_[static_cast<std::size_t>(order_[1])];
  const double c = axes_[static_cast<std::size_t>(order_[2])];
  const double pi = std::numbers::pi;
  if (a == c) return 4.0 * pi * a * a;
  // Legendre: S = 2πc² + 2πab (E(φ, k) sin²φ + F(φ, k) cos²φ) / sin φ with cos φ = c/a and
  // k² = a²(b² − c²) / (b²(a² − c²)).
  const double phi = std::acos(c / a);
  const double k = std::sqrt(a * a * (b - c) * (b + c) / (b * b * (a - c) * (a + c)));
  const double sin_phi = std::sin(phi);
  const double cos_phi = c / a;
  const double e = std::ellint_2(k, phi);
  const double f = std::ellint_1(k, phi);
  return 2.0 * pi * c * c +
         2.0 * pi * a * b * (e * sin_phi * sin_phi + f * cos_phi * cos_phi) / sin_phi;
}

}  // namespace rstruct::sampling
