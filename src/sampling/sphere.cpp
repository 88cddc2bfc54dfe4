#include "rstruct/sampling/sphere.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include "rstruct/core/error.hpp"
#include "rstruct/sampling/cube_sphere.hpp"

namespace rstruct::sampling {

Sphere::Sphere(double radius) : radius_(radius) {
  if (!is_supported_length(radius)) {
    std::ostringstream msg;
    msg << "sphere: radius must be in [" << kMinLength << ", " << kMaxLength << "], got " << radius;
    throw InvalidInput(msg.str());
  }
}

std::string Sphere::name() const {
  std::ostringstream out;
  out << "sphere(R=" << radius_ << ")";
  return out.str();
}

Vec3 Sphere::gradient(const Point3& x) const {
  const double n = norm(x);
  return n > 0.0 ? x / n : Vec3{1, 0, 0};
}

Point3 Sphere::closest_point(const Point3& x) const {
  const double n = norm(x);
  if (n == 0.0) return {radius_, 0, 0};  // every point of F is closest
  return x * (radius_ / n);
}

Box3 Sphere::bounding_box() const {
  return {{-radius_, -radius_, -radius_}, {radius_, radius_, radius_}};
}

std::string Sphere::medial_axis_description() const {
  return "the centre (0,0,0); lfs = R on the sphere";
}

ParamCell Sphere::chart_domain(int chart) const { return {chart, -1.0, 1.0, -1.0, 1.0}; }

Point3 Sphere::point(int chart, double u, double v) const {
  return cube_sphere_point(chart, u, v) * radius_;
}

double Sphere::area_element(int, double u, double v) const {
  return radius_ * radius_ * cube_sphere_area_element(u, v);
}

double Sphere::max_area_element(int) const { return radius_ * radius_; }

CellReach Sphere::cell_reach(const ParamCell& cell) const {
  const CubeSphereSpeeds s = cube_sphere_speed_bounds(cell);
  const double pad = 2.0 * kPointRounding * radius_;
  return {radius_ * s.su * 0.5 * (cell.u1 - cell.u0) + pad,
          radius_ * s.sv * 0.5 * (cell.v1 - cell.v0)};
}

double Sphere::area() const { return 4.0 * std::numbers::pi * radius_ * radius_; }

}  // namespace rstruct::sampling
