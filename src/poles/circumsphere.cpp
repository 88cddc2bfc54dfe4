#include "circumsphere.hpp"

#include <cmath>
#include <gmpxx.h>

#include "rstruct/core/assert.hpp"

namespace rstruct::poles::detail {
namespace {

/// Exact centre − a, rounded once per coordinate.
Vec3 exact_offset(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  mpq_class u[3], v[3], w[3];
  for (int i = 0; i < 3; ++i) {
    u[i] = mpq_class(b[i]) - mpq_class(a[i]);
    v[i] = mpq_class(c[i]) - mpq_class(a[i]);
    w[i] = mpq_class(d[i]) - mpq_class(a[i]);
  }
  const mpq_class vw[3] = {v[1] * w[2] - v[2] * w[1], v[2] * w[0] - v[0] * w[2],
                           v[0] * w[1] - v[1] * w[0]};
  const mpq_class wu[3] = {w[1] * u[2] - w[2] * u[1], w[2] * u[0] - w[0] * u[2],
                           w[0] * u[1] - w[1] * u[0]};
  const mpq_class uv[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                           u[0] * v[1] - u[1] * v[0]};
  const mpq_class den = 2 * (u[0] * vw[0] + u[1] * vw[1] + u[2] * vw[2]);
  RSTRUCT_ASSERT_MSG(sgn(den) != 0, "circumsphere of a flat tetrahedron");
  const mpq_class nu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
  const mpq_class nv = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
  const mpq_class nw = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
  Vec3 offset;
  for (int i = 0; i < 3; ++i) {
    const mpq_class x = (nu * vw[i] + nv * wu[i] + nw * uv[i]) / den;
    offset[static_cast<std::size_t>(i)] = x.get_d();
  }
  return offset;
}

}  // namespace

Circumsphere circumsphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const Vec3 u = b - a, v = c - a, w = d - a;
  const Vec3 vw = cross(v, w), wu = cross(w, u), uv = cross(u, v);
  const double det = dot(u, vw);
  const double nu = squared_norm(u), nv = squared_norm(v), nw = squared_norm(w);
  // |det| = |u||v||w|·(a sine product); below 2⁻²⁶ of |u||v||w| the floating-point centre
  // may lose more than half its bits, so it is computed exactly instead.
  const double scale = std::sqrt(nu * nv * nw);
  Vec3 offset;
  if (std::isfinite(det) && std::fabs(det) > 0x1p-26 * scale) {
    offset = (nu * vw + nv * wu + nw * uv) / (2.0 * det);
  } else {
    offset = exact_offset(a, b, c, d);
  }
  return {offset, squared_norm(offset)};
}

}  // namespace rstruct::poles::detail
