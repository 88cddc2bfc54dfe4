#include "rstruct/sampling/surface.hpp"

#include <algorithm>
#include <cmath>

#include "rstruct/core/error.hpp"

namespace rstruct::sampling {

namespace {
[[noreturn]] void no_parametrization(const Surface& s) {
  throw InvalidInput("surface " + s.name() + " has no parametrization");
}
}  // namespace

double Surface::lfs(const Point3& x) const {
  if (!has_known_lfs()) {
    throw InvalidInput("the local feature size of " + name() + " is not known");
  }
  double d = HUGE_VAL;
  if (const auto m = nearest_inner_medial_point(x)) d = std::min(d, distance(x, *m));
  if (const auto m = nearest_outer_medial_point(x)) d = std::min(d, distance(x, *m));
  return d;
}

Point3 project_along_gradient(const Surface& surface, Point3 x) {
  for (int i = 0; i < 100; ++i) {
    const double f = surface.value(x);
    const Vec3 g = surface.gradient(x);
    const double g2 = squared_norm(g);
    if (g2 == 0.0 || !std::isfinite(f)) break;
    const Vec3 step = g * (f / g2);
    x -= step;
    if (norm(step) <= 1e-16 * (1.0 + norm(x))) break;
  }
  return x;
}

ParamCell Surface::chart_domain(int) const { no_parametrization(*this); }
Point3 Surface::point(int, double, double) const { no_parametrization(*this); }
double Surface::area_element(int, double, double) const { no_parametrization(*this); }
double Surface::max_area_element(int) const { no_parametrization(*this); }
CellReach Surface::cell_reach(const ParamCell&) const { no_parametrization(*this); }

}  // namespace rstruct::sampling
