#include "rstruct/triangulation/orthosphere.hpp"

#include <cmath>
#include <gmpxx.h>

#include "rstruct/core/assert.hpp"

namespace rstruct::triangulation {

namespace {

/// Exact y (centre − a) of the orthosphere, rounded once per coordinate: the same formula
/// as below over GMP rationals. \pre abcd not flat.
Vec3 exact_offset(const Point3& a, double wa, const Point3& b, double wb, const Point3& c,
                  double wc, const Point3& d, double wd) {
  mpq_class u[3], v[3], w[3];
  for (std::size_t i = 0; i < 3; ++i) {
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
  RSTRUCT_ASSERT_MSG(sgn(den) != 0, "orthosphere of a flat cell");
  const mpq_class qa(wa);
  const mpq_class su = u[0] * u[0] + u[1] * u[1] + u[2] * u[2] - mpq_class(wb) + qa;
  const mpq_class sv = v[0] * v[0] + v[1] * v[1] + v[2] * v[2] - mpq_class(wc) + qa;
  const mpq_class sw = w[0] * w[0] + w[1] * w[1] + w[2] * w[2] - mpq_class(wd) + qa;
  Vec3 y;
  for (std::size_t i = 0; i < 3; ++i) {
    const mpq_class x = (su * vw[i] + sv * wu[i] + sw * uv[i]) / den;
    y[i] = x.get_d();
  }
  return y;
}

}  // namespace

Vec3 orthosphere_offset(const Point3& a, double wa, const Point3& b, double wb, const Point3& c,
                        double wc, const Point3& d, double wd) {
  const Vec3 u = b - a;
  const Vec3 v = c - a;
  const Vec3 w = d - a;
  const double su = squared_norm(u) - wb + wa;
  const double sv = squared_norm(v) - wc + wa;
  const double sw = squared_norm(w) - wd + wa;
  const Vec3 vw = cross(v, w);
  const Vec3 wu = cross(w, u);
  const Vec3 uv = cross(u, v);
  const double det = dot(u, vw);
  const double scale = std::sqrt(squared_norm(u) * squared_norm(v) * squared_norm(w));
  if (std::isfinite(det) && std::fabs(det) > 0x1p-26 * scale) {
    return (su * vw + sv * wu + sw * uv) / (2.0 * det);
  }
  return exact_offset(a, wa, b, wb, c, wc, d, wd);
}

}  // namespace rstruct::triangulation
