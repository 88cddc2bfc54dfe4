#pragma once
/// \file
/// Semi-static floating-point filters: evaluate the polynomial of polynomials.hpp in
/// doubles, bound its error by K·S (constants and the meaning of S in
/// filter_constants.hpp, proved by proofs/filter_bounds.cpp) and decide when the value
/// clears the bound. They return −1 or +1 when decided and kUndecided otherwise (also for
/// NaN, infinities, and column maxima outside the guard, including zero columns).

#include <cmath>

#include "rstruct/predicates/detail/filter_constants.hpp"
#include "rstruct/predicates/detail/polynomials.hpp"
#include "rstruct/geometry/vec3.hpp"

namespace rstruct::predicates::detail {

inline constexpr int kUndecided = 2;

/// Axes (u, v) of the coordinate plane obtained by dropping axis k, in cyclic order so
/// that the 2D orientation there is the k-th component of the normal.
inline constexpr int kAxisU[3] = {1, 2, 0};
inline constexpr int kAxisV[3] = {2, 0, 1};

inline double max2(double a, double b) { return a < b ? b : a; }
inline double abs_max3(double a, double b, double c) {
  return max2(max2(std::fabs(a), std::fabs(b)), std::fabs(c));
}
inline double abs_max4(double a, double b, double c, double d) {
  return max2(abs_max3(a, b, c), std::fabs(d));
}

/// ±1 if `ok` and |value| > bound, else kUndecided (NaN never decides). Branch-free
/// except for the rarely taken undecided case: the sign of a random input is
/// unpredictable, and a mispredicted branch costs more than the whole filter.
inline int decide(double value, double bound, bool ok = true) {
  const int pos = value > bound;
  const int neg = value < -bound;
  return (static_cast<int>(ok) & (pos | neg)) != 0 ? pos - neg : kUndecided;
}

/// The guard of filter_constants.hpp: the smallest column maximum is at least the
/// guard's minimum (so underflow stays negligible) and the computed value is finite (an
/// overflow anywhere makes it ±inf or NaN, as there are no divisions; an overflowing
/// bound is +inf and never decides). Bitwise &: no short-circuit branches.
inline bool in_guard(double smallest_column_max, double value, const filter::Guard& g) {
  return static_cast<bool>((smallest_column_max >= g.min_magnitude) &
                           (std::fabs(value) <= 0x1.fffffffffffffp1023));
}
inline double min3(double a, double b, double c) {
  const double ab = a < b ? a : b;
  return ab < c ? ab : c;
}

inline int orient3d_filter(const Point3& a, const Point3& b, const Point3& c,
                           const Point3& d) {
  const double bx = b.x - a.x, by = b.y - a.y, bz = b.z - a.z;
  const double cx = c.x - a.x, cy = c.y - a.y, cz = c.z - a.z;
  const double dx = d.x - a.x, dy = d.y - a.y, dz = d.z - a.z;
  const double mx = abs_max3(bx, cx, dx), my = abs_max3(by, cy, dy), mz = abs_max3(bz, cz, dz);
  const double value = det3(bx, by, bz, cx, cy, cz, dx, dy, dz);
  return decide(value, filter::kOrient3d * mx * my * mz,
                in_guard(min3(mx, my, mz), value, filter::kGuardDegree3));
}

/// Orientation of a, b, c projected on the coordinate plane that drops axis k.
inline int orient2d_filter(const Point3& a, const Point3& b, const Point3& c, int k) {
  const int u = kAxisU[k], v = kAxisV[k];
  const double bu = b[u] - a[u], bv = b[v] - a[v];
  const double cu = c[u] - a[u], cv = c[v] - a[v];
  const double mu = max2(std::fabs(bu), std::fabs(cu)), mv = max2(std::fabs(bv), std::fabs(cv));
  const double value = minor2(bu, bv, cu, cv);
  return decide(value, filter::kOrient2d * mu * mv, in_guard(mu < mv ? mu : mv, value, filter::kGuardDegree3));
}

/// The entries of the lifted determinant of a, b, c, d relative to e, as every filter of
/// the in-sphere and power tests computes them (the evaluation order that
/// proofs/filter_bounds.cpp analyses): the differences t = p − e, the weight differences
/// w_p − w_e (zero when not `weighted`) and the rows (t, |t|² − (w_p − w_e)).
struct LiftedDifferences {
  Point3 ta, tb, tc, td;
  double wa, wb, wc, wd;
  LiftedRows<double> rows;
};

/// Always inlined: the triangulation's conflict search computes it for every cell it visits.
template <bool weighted>
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
inline LiftedDifferences lifted_differences(const Point3& a, const Point3& b, const Point3& c,
                                            const Point3& d, const Point3& e, double aw,
                                            double bw, double cw, double dw, double ew) {
  LiftedDifferences l;
  l.ta = a - e, l.tb = b - e, l.tc = c - e, l.td = d - e;
  if constexpr (weighted) {
    l.wa = aw - ew, l.wb = bw - ew, l.wc = cw - ew, l.wd = dw - ew;
  } else {
    l.wa = l.wb = l.wc = l.wd = 0;
    (void)aw, (void)bw, (void)cw, (void)dw, (void)ew;
  }
  l.rows = {l.ta.x, l.ta.y, l.ta.z, lifted_height(l.ta.x, l.ta.y, l.ta.z, l.wa),
            l.tb.x, l.tb.y, l.tb.z, lifted_height(l.tb.x, l.tb.y, l.tb.z, l.wb),
            l.tc.x, l.tc.y, l.tc.z, lifted_height(l.tc.x, l.tc.y, l.tc.z, l.wc),
            l.td.x, l.td.y, l.td.z, lifted_height(l.td.x, l.td.y, l.td.z, l.wd)};
  return l;
}

/// Sign of −det[(p − e, |p − e|² − (w_p − w_e))] for p = a, b, c, d (power test; with
/// `weighted` false the weights are ignored: insphere).
template <bool weighted>
int lifted4_filter_points(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                          const Point3& e, double aw, double bw, double cw, double dw,
                          double ew) {
  const auto [ta, tb, tc, td, wa, wb, wc, wd, rows] =
      lifted_differences<weighted>(a, b, c, d, e, aw, bw, cw, dw, ew);
  const double mx = abs_max4(ta.x, tb.x, tc.x, td.x);
  const double my = abs_max4(ta.y, tb.y, tc.y, td.y);
  const double mz = abs_max4(ta.z, tb.z, tc.z, td.z);
  const double big = max2(max2(mx, my), mz);
  const double value = lifted_det4_negated(rows);
  const filter::Guard& g = filter::kGuardDegree5;
  const bool ok = in_guard(min3(mx, my, mz), value, g);
  if constexpr (weighted) {
    const double mw = abs_max4(wa, wb, wc, wd);
    return decide(value, filter::kPowerTest * mx * my * mz * max2(big * big, mw), ok);
  } else {
    return decide(value, filter::kInsphere * mx * my * mz * (big * big), ok);
  }
}

template <bool weighted>
int lifted4_filter(const WeightedPoint& a, const WeightedPoint& b, const WeightedPoint& c,
                   const WeightedPoint& d, const WeightedPoint& e) {
  return lifted4_filter_points<weighted>(a.c, b.c, c.c, d.c, e.c, a.w, b.w, c.w, d.w, e.w);
}

/// lifted4_filter<false> on unweighted points.
inline int insphere_filter(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                           const Point3& e) {
  return lifted4_filter_points<false>(a, b, c, d, e, 0, 0, 0, 0, 0);
}

/// Sign of the projected lifted determinant det[(p_u − e_u, p_v − e_v, h_p)] for
/// p = a, b, c, with h_p = |p − e|² − (w_p − w_e) in 3D and (u, v) dropping axis k.
inline int coplanar_power_filter(const WeightedPoint& a, const WeightedPoint& b,
                                 const WeightedPoint& c, const WeightedPoint& e, int k) {
  const int u = kAxisU[k], v = kAxisV[k];
  const Point3 ta = a.c - e.c, tb = b.c - e.c, tc = c.c - e.c;
  const double wa = a.w - e.w, wb = b.w - e.w, wc = c.w - e.w;
  const double ha = lifted_height(ta.x, ta.y, ta.z, wa);
  const double hb = lifted_height(tb.x, tb.y, tb.z, wb);
  const double hc = lifted_height(tc.x, tc.y, tc.z, wc);
  const double value = lifted_det3(ta[u], ta[v], ha, tb[u], tb[v], hb, tc[u], tc[v], hc);
  const double mu = abs_max3(ta[u], tb[u], tc[u]), mv = abs_max3(ta[v], tb[v], tc[v]);
  const double big = max2(max2(abs_max3(ta.x, tb.x, tc.x), abs_max3(ta.y, tb.y, tc.y)),
                          abs_max3(ta.z, tb.z, tc.z));
  const double mw = abs_max3(wa, wb, wc);
  const filter::Guard& g = filter::kGuardDegree5;
  return decide(value, filter::kCoplanarPower * mu * mv * max2(big * big, mw),
                in_guard(mu < mv ? mu : mv, value, g));
}

/// Sign of det[(a_q − e_q, h_a); (b_q − e_q, h_b)], h as above, q = axis k.
inline int collinear_power_filter(const WeightedPoint& a, const WeightedPoint& b,
                                  const WeightedPoint& e, int k) {
  const Point3 ta = a.c - e.c, tb = b.c - e.c;
  const double wa = a.w - e.w, wb = b.w - e.w;
  const double ha = lifted_height(ta.x, ta.y, ta.z, wa);
  const double hb = lifted_height(tb.x, tb.y, tb.z, wb);
  const double value = lifted_det2(ta[k], ha, tb[k], hb);
  const double mq = max2(std::fabs(ta[k]), std::fabs(tb[k]));
  const double big = max2(max2(max2(std::fabs(ta.x), std::fabs(tb.x)),
                               max2(std::fabs(ta.y), std::fabs(tb.y))),
                          max2(std::fabs(ta.z), std::fabs(tb.z)));
  const double mw = max2(std::fabs(wa), std::fabs(wb));
  const filter::Guard& g = filter::kGuardDegree5;
  return decide(value, filter::kCollinearPower * mq * max2(big * big, mw),
                in_guard(mq, value, g));
}

inline int squared_distance_difference_filter(const Point3& x, const Point3& p,
                                              const Point3& q) {
  const Point3 tp = x - p, tq = x - q;
  const double value = squared_distance_difference(tp.x, tp.y, tp.z, tq.x, tq.y, tq.z);
  const double big = max2(abs_max3(tp.x, tp.y, tp.z), abs_max3(tq.x, tq.y, tq.z));
  return decide(value, filter::kSquaredDistanceDifference * (big * big),
                in_guard(big, value, filter::kGuardDegree2));
}

inline int power_difference_filter(const Point3& x, const WeightedPoint& p,
                                   const WeightedPoint& q) {
  const Point3 tp = x - p.c, tq = x - q.c;
  const double value = power_difference(tp.x, tp.y, tp.z, p.w, tq.x, tq.y, tq.z, q.w);
  const double big = max2(abs_max3(tp.x, tp.y, tp.z), abs_max3(tq.x, tq.y, tq.z));
  const double mw = max2(std::fabs(p.w), std::fabs(q.w));
  const filter::Guard& g = filter::kGuardDegree2;
  return decide(value, filter::kPowerDifference * max2(big * big, mw),
                in_guard(big, value, g));
}

inline int power_value_filter(const Point3& x, const WeightedPoint& p) {
  const Point3 t = x - p.c;
  const double value = power_value(t.x, t.y, t.z, p.w);
  const double big = abs_max3(t.x, t.y, t.z);
  const double mw = std::fabs(p.w);
  const filter::Guard& g = filter::kGuardDegree2;
  return decide(value, filter::kPowerValue * max2(big * big, mw),
                in_guard(big, value, g));
}

inline int ball_side_filter(const Point3& x, const Point3& centre, double r) {
  const Point3 t = x - centre;
  const double value = ball_side_value(t.x, t.y, t.z, r);
  const double big = max2(abs_max3(t.x, t.y, t.z), std::fabs(r));
  return decide(value, filter::kBallSide * (big * big),
                in_guard(abs_max3(t.x, t.y, t.z), value, filter::kGuardDegree2));
}

}  // namespace rstruct::predicates::detail
