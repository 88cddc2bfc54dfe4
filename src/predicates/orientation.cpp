#include <cmath>
#include <string>

#include "rstruct/predicates/detail/counting.hpp"
#include "predicates/exact_stage.hpp"
#include "rstruct/predicates/detail/filters.hpp"
#include "predicates/plane_axis.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/predicates/predicates.hpp"

namespace rstruct::predicates {
namespace detail {

int orient2d_axis(const Point3& a, const Point3& b, const Point3& c, int k) {
  const int f = orient2d_filter(a, b, c, k);
  if (f != kUndecided) {
    RSTRUCT_PREDICATE_COUNT(orient2d, filter);
    return f;
  }
  RSTRUCT_PREDICATE_COUNT(orient2d, exact);
  return orient2d_exact(a, b, c, k);
}

PlaneAxis choose_plane_axis(const Point3& a, const Point3& b, const Point3& c,
                            const char* where) {
  // Try the axis of the largest approximate normal component first: its projection is
  // the best conditioned, and it is non-zero unless the normal is (nearly) zero.
  const Vec3 n = cross(b - a, c - a);
  int first = 0;
  if (std::fabs(n.y) > std::fabs(n[static_cast<std::size_t>(first)])) first = 1;
  if (std::fabs(n.z) > std::fabs(n[static_cast<std::size_t>(first)])) first = 2;
  for (int i = 0; i < 3; ++i) {
    const int k = (first + i) % 3;
    const int o = orient2d_axis(a, b, c, k);
    if (o != 0) return {k, o};
  }
  throw InvalidInput(std::string("predicates::") + where +
                     ": the three points spanning the plane are collinear");
}

Sign orient3d_after_filter(const Point3& a, const Point3& b, const Point3& c,
                          const Point3& d) {
  RSTRUCT_PREDICATE_COUNT(orient3d, exact);
  return static_cast<Sign>(orient3d_exact(a, b, c, d));
}

}  // namespace detail

Sign coplanar_orientation(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const detail::PlaneAxis axis = detail::choose_plane_axis(a, b, c, "coplanar_orientation");
  return static_cast<Sign>(detail::orient2d_axis(a, b, d, axis.drop) * axis.orientation);
}

}  // namespace rstruct::predicates
