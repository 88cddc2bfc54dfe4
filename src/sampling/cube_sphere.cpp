#include "rstruct/sampling/cube_sphere.hpp"

#include <algorithm>
#include <cmath>

namespace rstruct::sampling {

Vec3 cube_sphere_direction(int face, double u, double v) {
  const int axis = face / 2;
  Vec3 w;
  w[static_cast<std::size_t>(axis)] = (face % 2 == 0) ? 1.0 : -1.0;
  w[static_cast<std::size_t>((axis + 1) % 3)] = u;
  w[static_cast<std::size_t>((axis + 2) % 3)] = v;
  return w;
}

Vec3 cube_sphere_point(int face, double u, double v) {
  return normalized(cube_sphere_direction(face, u, v));
}

double cube_sphere_area_element(double u, double v) {
  const double q = 1.0 + u * u + v * v;
  return 1.0 / (q * std::sqrt(q));
}

double min_abs_over(double lo, double hi) {
  if (lo <= 0.0 && hi >= 0.0) return 0.0;
  return std::min(std::fabs(lo), std::fabs(hi));
}

double max_abs_over(double lo, double hi) { return std::max(std::fabs(lo), std::fabs(hi)); }

CubeSphereSpeeds cube_sphere_speed_bounds(const ParamCell& cell) {
  const double umin = min_abs_over(cell.u0, cell.u1);
  const double umax = max_abs_over(cell.u0, cell.u1);
  const double vmin = min_abs_over(cell.v0, cell.v1);
  const double vmax = max_abs_over(cell.v0, cell.v1);
  const double denominator = 1.0 + umin * umin + vmin * vmin;
  return {std::sqrt(1.0 + vmax * vmax) / denominator, std::sqrt(1.0 + umax * umax) / denominator};
}

}  // namespace rstruct::sampling
