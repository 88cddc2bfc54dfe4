#include "rstruct/sampling/torus.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "rstruct/core/error.hpp"

namespace rstruct::sampling {

Torus::Torus(double major_radius, double minor_radius)
    : major_(major_radius), minor_(minor_radius) {
  if (!is_supported_length(major_) || !is_supported_length(minor_) || major_ <= minor_) {
    std::ostringstream msg;
    msg << "torus: need radii in [" << kMinLength << ", " << kMaxLength
        << "] with R > a (a ring torus), got R = " << major_ << ", a = " << minor_;
    throw InvalidInput(msg.str());
  }
}

std::string Torus::name() const {
  std::ostringstream out;
  out << "torus(R=" << major_ << ", a=" << minor_ << ")";
  return out.str();
}

double Torus::value(const Point3& x) const {
  const double rho = std::hypot(x.x, x.y);
  return std::hypot(rho - major_, x.z) - minor_;
}

Point3 Torus::core_point(const Point3& x) const {
  const double rho = std::hypot(x.x, x.y);
  if (rho == 0.0) return {major_, 0, 0};
  return {major_ * x.x / rho, major_ * x.y / rho, 0.0};
}

Vec3 Torus::gradient(const Point3& x) const {
  const Vec3 d = x - core_point(x);
  const double n = norm(d);
  if (n == 0.0) return normalized(core_point(x));
  return d / n;
}

Point3 Torus::closest_point(const Point3& x) const {
  const Point3 c = core_point(x);
  const Vec3 d = x - c;
  const double n = norm(d);
  if (n == 0.0) return c + normalized(c) * minor_;  // x on the core circle: any is closest
  return c + d * (minor_ / n);
}

Box3 Torus::bounding_box() const {
  const double r = major_ + minor_;
  return {{-r, -r, -minor_}, {r, r, minor_}};
}

std::optional<Point3> Torus::nearest_inner_medial_point(const Point3& x) const {
  return core_point(x);
}

std::string Torus::medial_axis_description() const {
  return "inner: the core circle rho = R, z = 0; outer: the z axis";
}

// The chart ends at the double nearest 2π, just below 2π; the sliver of F left out lies
// within 1e-15 of the cells at the chart's edge, well inside their rounding pad.
ParamCell Torus::chart_domain(int chart) const {
  return {chart, 0.0, 2.0 * std::numbers::pi, 0.0, 2.0 * std::numbers::pi};
}

Point3 Torus::point(int, double u, double v) const {
  const double ring = major_ + minor_ * std::cos(v);
  return {ring * std::cos(u), ring * std::sin(u), minor_ * std::sin(v)};
}

double Torus::area_element(int, double, double v) const {
  return minor_ * (major_ + minor_ * std::cos(v));
}

double Torus::max_area_element(int) const { return minor_ * (major_ + minor_); }

double max_cos_over(double lo, double hi) {
  const double two_pi = 2.0 * std::numbers::pi;
  // A multiple of 2π inside [lo, hi] gives the maximum 1. (Slightly conservative near the
  // boundary because 2π is rounded: we test with a small outward allowance.)
  const double k = std::ceil((lo - 1e-12) / two_pi);
  if (k * two_pi <= hi + 1e-12) return 1.0;
  return std::max(std::cos(lo), std::cos(hi)) + 1e-15;
}

CellReach Torus::cell_reach(const ParamCell& cell) const {
  // |P_θ| = R + a cos φ, |P_φ| = a.
  const double speed_u = major_ + minor_ * max_cos_over(cell.v0, cell.v1);
  const double pad = 2.0 * kPointRounding * (major_ + minor_);
  return {speed_u * 0.5 * (cell.u1 - cell.u0) + pad, minor_ * 0.5 * (cell.v1 - cell.v0)};
}

double Torus::area() const { return 4.0 * std::numbers::pi * std::numbers::pi * major_ * minor_; }

}  // namespace rstruct::sampling
