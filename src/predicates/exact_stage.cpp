#include "predicates/exact_stage.hpp"

#include <gmpxx.h>

#include <array>
#include <cmath>
#include <initializer_list>
#include <string>

#include "predicates/polynomials.hpp"
#include "predicates/scaled_integer.hpp"
#include "rstruct/core/error.hpp"

namespace rstruct::predicates::detail {
namespace {

using Z = mpz_class;

/// Exact integer images of a few points at one common scale.
template <std::size_t N>
struct ScaledPoints {
  std::array<std::array<Z, 3>, N> c;  // coordinates / 2^s
  std::array<Z, N> w;                 // weights / 2^(2s)
};

template <std::size_t N>
ScaledPoints<N> scale_points(const std::array<const WeightedPoint*, N>& pts, bool weighted) {
  ScaleFinder finder;
  for (const WeightedPoint* p : pts) {
    for (int i = 0; i < 3; ++i) finder.add_coordinate(p->c[static_cast<std::size_t>(i)]);
    if (weighted) finder.add_weight(p->w);
  }
  const int s = finder.unit();
  ScaledPoints<N> out;
  for (std::size_t j = 0; j < N; ++j) {
    for (std::size_t i = 0; i < 3; ++i) set_scaled(out.c[j][i], pts[j]->c[i], s);
    if (weighted) set_scaled(out.w[j], pts[j]->w, 2 * s);
  }
  return out;
}

void require_finite_points(const char* where, std::initializer_list<const WeightedPoint*> pts) {
  for (const WeightedPoint* p : pts) require_finite(where, {p->c.x, p->c.y, p->c.z, p->w});
}

}  // namespace

void require_finite(const char* where, std::initializer_list<double> values) {
  for (const double v : values) {
    if (!std::isfinite(v)) {
      throw InvalidInput(std::string("predicates::") + where +
                         ": non-finite input coordinate or weight (" + std::to_string(v) + ")");
    }
  }
}

int orient3d_exact(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const WeightedPoint wa{a, 0}, wb{b, 0}, wc{c, 0}, wd{d, 0};
  require_finite_points("orient3d", {&wa, &wb, &wc, &wd});
  const auto s = scale_points<4>({&wa, &wb, &wc, &wd}, false);
  std::array<std::array<Z, 3>, 3> t;
  for (std::size_t j = 0; j < 3; ++j) {
    for (std::size_t i = 0; i < 3; ++i) t[j][i] = s.c[j + 1][i] - s.c[0][i];
  }
  return sign_int(det3(t[0][0], t[0][1], t[0][2], t[1][0], t[1][1], t[1][2], t[2][0], t[2][1],
                       t[2][2]));
}

int orient2d_exact(const Point3& a, const Point3& b, const Point3& c, int k) {
  const WeightedPoint wa{a, 0}, wb{b, 0}, wc{c, 0};
  require_finite_points("orient2d", {&wa, &wb, &wc});
  const auto s = scale_points<3>({&wa, &wb, &wc}, false);
  const auto u = static_cast<std::size_t>((k + 1) % 3), v = static_cast<std::size_t>((k + 2) % 3);
  const Z bu = s.c[1][u] - s.c[0][u], bv = s.c[1][v] - s.c[0][v];
  const Z cu = s.c[2][u] - s.c[0][u], cv = s.c[2][v] - s.c[0][v];
  return sign_int(minor2(bu, bv, cu, cv));
}

int lifted4_exact(const WeightedPoint& a, const WeightedPoint& b, const WeightedPoint& c,
                  const WeightedPoint& d, const WeightedPoint& e) {
  require_finite_points("power_test", {&a, &b, &c, &d, &e});
  const auto s = scale_points<5>({&a, &b, &c, &d, &e}, true);
  std::array<std::array<Z, 4>, 4> r;  // rows (x, y, z, lifted height) relative to e
  for (std::size_t j = 0; j < 4; ++j) {
    for (std::size_t i = 0; i < 3; ++i) r[j][i] = s.c[j][i] - s.c[4][i];
    const Z tw = s.w[j] - s.w[4];
    r[j][3] = lifted_height(r[j][0], r[j][1], r[j][2], tw);
  }
  const LiftedRows<Z> rows{r[0][0], r[0][1], r[0][2], r[0][3], r[1][0], r[1][1], r[1][2], r[1][3],
                           r[2][0], r[2][1], r[2][2], r[2][3], r[3][0], r[3][1], r[3][2], r[3][3]};
  return sign_int(lifted_det4_negated(rows));
}

int coplanar_power_exact(const WeightedPoint& a, const WeightedPoint& b,
                         const WeightedPoint& c, const WeightedPoint& e, int k) {
  require_finite_points("coplanar_power_test", {&a, &b, &c, &e});
  const auto s = scale_points<4>({&a, &b, &c, &e}, true);
  const auto u = static_cast<std::size_t>((k + 1) % 3), v = static_cast<std::size_t>((k + 2) % 3);
  std::array<std::array<Z, 3>, 3> r;  // rows (u, v, lifted height) relative to e
  for (std::size_t j = 0; j < 3; ++j) {
    const Z tx = s.c[j][0] - s.c[3][0], ty = s.c[j][1] - s.c[3][1], tz = s.c[j][2] - s.c[3][2];
    const Z tw = s.w[j] - s.w[3];
    r[j][0] = s.c[j][u] - s.c[3][u];
    r[j][1] = s.c[j][v] - s.c[3][v];
    r[j][2] = lifted_height(tx, ty, tz, tw);
  }
  return sign_int(lifted_det3(r[0][0], r[0][1], r[0][2], r[1][0], r[1][1], r[1][2], r[2][0],
                              r[2][1], r[2][2]));
}

int collinear_power_exact(const WeightedPoint& a, const WeightedPoint& b,
                          const WeightedPoint& e, int k) {
  require_finite_points("collinear_power_test", {&a, &b, &e});
  const auto s = scale_points<3>({&a, &b, &e}, true);
  const auto q = static_cast<std::size_t>(k);
  std::array<Z, 2> tq, h;
  for (std::size_t j = 0; j < 2; ++j) {
    const Z tx = s.c[j][0] - s.c[2][0], ty = s.c[j][1] - s.c[2][1], tz = s.c[j][2] - s.c[2][2];
    const Z tw = s.w[j] - s.w[2];
    tq[j] = s.c[j][q] - s.c[2][q];
    h[j] = lifted_height(tx, ty, tz, tw);
  }
  return sign_int(lifted_det2(tq[0], h[0], tq[1], h[1]));
}

int squared_distance_difference_exact(const Point3& x, const Point3& p, const Point3& q) {
  return power_difference_exact(x, WeightedPoint{p, 0}, WeightedPoint{q, 0});
}

int power_difference_exact(const Point3& x, const WeightedPoint& p, const WeightedPoint& q) {
  const WeightedPoint wx{x, 0};
  require_finite_points("compare_power_distance", {&wx, &p, &q});
  const auto s = scale_points<3>({&wx, &p, &q}, true);
  std::array<std::array<Z, 3>, 2> t;
  for (std::size_t j = 0; j < 2; ++j) {
    for (std::size_t i = 0; i < 3; ++i) t[j][i] = s.c[0][i] - s.c[j + 1][i];
  }
  return sign_int(power_difference(t[0][0], t[0][1], t[0][2], s.w[1], t[1][0], t[1][1],
                                   t[1][2], s.w[2]));
}

int power_value_exact(const Point3& x, const WeightedPoint& p) {
  const WeightedPoint wx{x, 0};
  require_finite_points("power_sign", {&wx, &p});
  const auto s = scale_points<2>({&wx, &p}, true);
  std::array<Z, 3> t;
  for (std::size_t i = 0; i < 3; ++i) t[i] = s.c[0][i] - s.c[1][i];
  return sign_int(power_value(t[0], t[1], t[2], s.w[1]));
}

int ball_side_exact(const Point3& x, const Point3& centre, double r) {
  require_finite("side_of_ball", {x.x, x.y, x.z, centre.x, centre.y, centre.z, r});
  // The radius is a length: it joins the coordinates' scale through a fake third point.
  const WeightedPoint wx{x, 0}, wc{centre, 0}, wr{{r, 0, 0}, 0};
  const auto s = scale_points<3>({&wx, &wc, &wr}, false);
  std::array<Z, 3> t;
  for (std::size_t i = 0; i < 3; ++i) t[i] = s.c[0][i] - s.c[1][i];
  return sign_int(ball_side_value(t[0], t[1], t[2], s.c[2][0]));
}

}  // namespace rstruct::predicates::detail
