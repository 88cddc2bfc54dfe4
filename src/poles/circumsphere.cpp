#include "circumsphere.hpp"

#include "rstruct/triangulation/orthosphere.hpp"

namespace rstruct::poles::detail {

Circumsphere circumsphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const Vec3 offset = triangulation::orthosphere_offset(a, 0.0, b, 0.0, c, 0.0, d, 0.0);
  return {offset, squared_norm(offset)};
}

}  // namespace rstruct::poles::detail
