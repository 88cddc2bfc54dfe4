#include "rstruct/sampling/double_torus.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "rstruct/core/error.hpp"
#include "rstruct/sampling/implicit_mesher.hpp"

namespace rstruct::sampling {

DoubleTorus::DoubleTorus(DoubleTorusParameters parameters) : p_(parameters) {
  const double values[] = {p_.big_major,   p_.big_minor,      p_.small_major,
                           p_.small_minor, p_.small_centre_x, p_.blend};
  for (double v : values) {
    if (!std::isfinite(v)) throw InvalidInput("double torus: parameters must be finite");
  }
  for (double v : {p_.big_major, p_.big_minor, p_.small_major, p_.small_minor, p_.blend}) {
    if (!is_supported_length(v)) {
      throw InvalidInput("double torus: radii and blend must be in [1e-90, 1e90]");
    }
  }
  if (std::fabs(p_.small_centre_x) > kMaxLength) {
    throw InvalidInput("double torus: centre offset out of range");
  }
  if (p_.big_minor <= 0.0 || p_.small_minor <= 0.0 || p_.big_major <= p_.big_minor ||
      p_.small_major <= p_.small_minor || p_.blend <= 0.0) {
    throw InvalidInput("double torus: need R_i > a_i > 0 for both rings and blend > 0");
  }
}

std::string DoubleTorus::name() const {
  std::ostringstream out;
  out << "double-torus(R1=" << p_.big_major << ", a1=" << p_.big_minor << ", R2=" << p_.small_major
      << ", a2=" << p_.small_minor << ", c2=" << p_.small_centre_x << ", k=" << p_.blend << ")";
  return out.str();
}

double DoubleTorus::torus_distance(int i, const Point3& x, Vec3* gradient) const {
  const double cx = i == 0 ? 0.0 : p_.small_centre_x;
  const double major = i == 0 ? p_.big_major : p_.small_major;
  const double minor = i == 0 ? p_.big_minor : p_.small_minor;
  const double qx = x.x - cx;
  // sqrt of sums rather than hypot: no overflow is possible at this surface's scale, and
  // hypot is several times slower.
  const double rho = std::sqrt(qx * qx + x.y * x.y);
  const double radial = rho - major;
  const double len = std::sqrt(radial * radial + x.z * x.z);
  if (gradient != nullptr) {
    if (len == 0.0 || rho == 0.0) {
      *gradient = {0, 0, 1};  // on the core circle or the axis: not differentiable
    } else {
      *gradient = {radial / len * qx / rho, radial / len * x.y / rho, x.z / len};
    }
  }
  return len - minor;
}

double DoubleTorus::value(const Point3& x) const {
  const double d1 = torus_distance(0, x, nullptr);
  const double d2 = torus_distance(1, x, nullptr);
  const double m = std::min(d1, d2);
  const double k = p_.blend;
  return m - k * std::log(std::exp(-(d1 - m) / k) + std::exp(-(d2 - m) / k));
}

Vec3 DoubleTorus::gradient(const Point3& x) const {
  Vec3 g1, g2;
  const double d1 = torus_distance(0, x, &g1);
  const double d2 = torus_distance(1, x, &g2);
  const double m = std::min(d1, d2);
  const double w1 = std::exp(-(d1 - m) / p_.blend);
  const double w2 = std::exp(-(d2 - m) / p_.blend);
  return (g1 * w1 + g2 * w2) / (w1 + w2);
}

Point3 DoubleTorus::project(const Point3& x) const { return project_along_gradient(*this, x); }

Point3 DoubleTorus::closest_point(const Point3& x) const {
  Point3 p = project(x);
  for (int i = 0; i < 200; ++i) {
    const Vec3 n = normal(p);
    const Vec3 d = x - p;
    const Vec3 tangential = d - n * dot(d, n);
    if (norm(tangential) <= 1e-15 * (1.0 + norm(d))) break;
    const Point3 q = project(p + tangential);
    const double moved = distance(q, p);
    p = q;
    if (moved <= 1e-16 * (1.0 + norm(p))) break;
  }
  return p;
}

Box3 DoubleTorus::bounding_box() const {
  // The smooth minimum is ≥ min(d₁, d₂) − k ln 2, so F lies within k ln 2 of the union.
  const double pad = p_.blend * std::log(2.0);
  const double r1 = p_.big_major + p_.big_minor + pad;
  const double r2 = p_.small_major + p_.small_minor + pad;
  const double h = std::max(p_.big_minor, p_.small_minor) + pad;
  Box3 box;
  box.add({-r1, -r1, -h});
  box.add({r1, r1, h});
  box.add({p_.small_centre_x - r2, -r2, -h});
  box.add({p_.small_centre_x + r2, r2, h});
  return box;
}

double DoubleTorus::meshing_step() const { return std::min(p_.big_minor, p_.small_minor) / 12.0; }

double DoubleTorus::area() const {
  std::call_once(area_once_, [this] {
    const TriangleMesh mesh = mesh_implicit_surface(*this, meshing_step(), true);
    area_ = mesh_area(mesh);
  });
  return area_;
}

}  // namespace rstruct::sampling
