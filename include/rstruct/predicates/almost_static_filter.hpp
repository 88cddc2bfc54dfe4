#pragma once
/// \file
/// Almost-static filters (Devillers & Pion, "Efficient exact geometric predicates for
/// Delaunay triangulations", ALENEX 2003, section 3): when every input point of a
/// predicate is known to lie in a box, the semi-static error bound K·S of
/// detail/filter_constants.hpp is evaluated once, with the box's extents in place of the
/// column maxima, so that a call costs the plain floating-point evaluation and one
/// comparison. A call the bound cannot decide goes to the semi-static predicate of
/// predicates.hpp (its own filter, then the exact stage), so every answer is exact.
///
/// Why the constants carry over (no new constant): proofs/filter_bounds.cpp normalises
/// each column of differences by an upper bound m of its computed magnitudes and bounds
/// the error by K times the product S of those m; any upper bound serves, and for p, q in
/// the box [lo, hi] the computed |fl(p_i − q_i)| ≤ fl(hi_i − lo_i) = W_i because rounding to
/// nearest is monotone. The guards of filter_constants.hpp then apply to W: with some
/// W_i below the guard's minimum the bound is +inf (never decides). An overflowing bound
/// is +inf as well, and a call whose value is not finite is not decided.

#include <cmath>
#include <initializer_list>
#include <string>

#include "rstruct/core/assert.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/geometry/vec3.hpp"
#include "rstruct/predicates/detail/filters.hpp"
#include "rstruct/predicates/predicates.hpp"

namespace rstruct::predicates {

/// orient3d and insphere for inputs in a box fixed in advance (e.g. the bounding box of a
/// triangulation's points). Same results as the free functions of predicates.hpp.
class AlmostStaticFilter {
 public:
  /// Filters for points p with lo ≤ p ≤ hi coordinate-wise.
  /// \throws InvalidInput if a bound is not finite or lo > hi on some axis.
  AlmostStaticFilter(const Point3& lo, const Point3& hi) : lo_(lo), hi_(hi) {
    for (std::size_t i = 0; i < 3; ++i) {
      if (!std::isfinite(lo[i]) || !std::isfinite(hi[i]) || lo[i] > hi[i]) {
        throw InvalidInput("AlmostStaticFilter: the box [lo, hi] is empty or not finite (axis " +
                           std::to_string(i) + ")");
      }
    }
    const double wx = hi.x - lo.x, wy = hi.y - lo.y, wz = hi.z - lo.z;
    const double smallest = detail::min3(wx, wy, wz);
    const double big = detail::max2(detail::max2(wx, wy), wz);
    // The same floating-point expressions as the semi-static filters (filters.hpp), so
    // the constants' rounding allowance (bound_roundings) covers them.
    if (smallest >= detail::filter::kGuardDegree3.min_magnitude) {
      orient3d_bound_ = detail::filter::kOrient3d * wx * wy * wz;
    }
    if (smallest >= detail::filter::kGuardDegree5.min_magnitude) {
      insphere_bound_ = detail::filter::kInsphere * wx * wy * wz * (big * big);
    }
  }

  /// Also bounds the weights: power_test_filter_two_stage then has a static bound for
  /// weighted points with wlo ≤ w ≤ whi (its weight column is bounded by fl(whi − wlo),
  /// as the coordinates by the box's extents).
  /// \throws InvalidInput if a bound is not finite or wlo > whi.
  void set_weight_range(double wlo, double whi) {
    if (!std::isfinite(wlo) || !std::isfinite(whi) || wlo > whi) {
      throw InvalidInput("AlmostStaticFilter: the weight range [wlo, whi] is empty or not finite");
    }
    wlo_ = wlo;
    whi_ = whi;
    const double wx = hi_.x - lo_.x, wy = hi_.y - lo_.y, wz = hi_.z - lo_.z;
    const double smallest = detail::min3(wx, wy, wz);
    const double big = detail::max2(detail::max2(wx, wy), wz);
    const double ww = whi - wlo;
    power_test_bound_ = smallest >= detail::filter::kGuardDegree5.min_magnitude
                            ? detail::filter::kPowerTest * wx * wy * wz * detail::max2(big * big, ww)
                            : HUGE_VAL;
  }

  /// predicates::orient3d(a, b, c, d). \pre a, b, c, d lie in the box (checked, throwing
  /// InvalidInput, when built with -Dchecks=expensive or above).
  Sign orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) const {
    if constexpr (check_level() >= 2) require_in_box({&a, &b, &c, &d});
    const double value = detail::det3(b.x - a.x, b.y - a.y, b.z - a.z, c.x - a.x, c.y - a.y,
                                      c.z - a.z, d.x - a.x, d.y - a.y, d.z - a.z);
    const int f = detail::decide(value, orient3d_bound_, std::fabs(value) <= kMaxFinite);
    if (f != detail::kUndecided) [[likely]] {
      RSTRUCT_PREDICATE_COUNT(orient3d, filter);
      return static_cast<Sign>(f);
    }
    return predicates::orient3d(a, b, c, d);
  }

  /// orient3d, with the semi-static bound of detail::orient3d_filter applied to the same
  /// computed value where the box bound cannot decide (flat cells of a dense sample in a
  /// large box), before the exact stage: one evaluation instead of two. Same results.
  Sign orient3d_two_stage(const Point3& a, const Point3& b, const Point3& c,
                          const Point3& d) const {
    if constexpr (check_level() >= 2) require_in_box({&a, &b, &c, &d});
    const double bx = b.x - a.x, by = b.y - a.y, bz = b.z - a.z;
    const double cx = c.x - a.x, cy = c.y - a.y, cz = c.z - a.z;
    const double dx = d.x - a.x, dy = d.y - a.y, dz = d.z - a.z;
    const double value = detail::det3(bx, by, bz, cx, cy, cz, dx, dy, dz);
    const int f = detail::decide(value, orient3d_bound_, std::fabs(value) <= kMaxFinite);
    if (f != detail::kUndecided) [[likely]] {
      RSTRUCT_PREDICATE_COUNT(orient3d, filter);
      return static_cast<Sign>(f);
    }
    // As detail::orient3d_filter.
    const double mx = detail::abs_max3(bx, cx, dx), my = detail::abs_max3(by, cy, dy),
                 mz = detail::abs_max3(bz, cz, dz);
    const int g = detail::decide(
        value, detail::filter::kOrient3d * mx * my * mz,
        detail::in_guard(detail::min3(mx, my, mz), value, detail::filter::kGuardDegree3));
    if (g != detail::kUndecided) {
      RSTRUCT_PREDICATE_COUNT(orient3d, filter);
      return static_cast<Sign>(g);
    }
    return detail::orient3d_after_filter(a, b, c, d);
  }

  /// predicates::insphere(a, b, c, d, e). \pre as for orient3d.
  Sign insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                const Point3& e) const {
    const int f = insphere_filter(a, b, c, d, e);
    if (f != detail::kUndecided) [[likely]] return static_cast<Sign>(f);
    return predicates::insphere(a, b, c, d, e);
  }

  /// The filter stage alone: −1 or +1 (the sign of insphere(a, b, c, d, e), hence also of
  /// any perturbed version) when the box bound decides, detail::kUndecided otherwise.
  /// \pre as for orient3d.
  int insphere_filter(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                      const Point3& e) const {
    if constexpr (check_level() >= 2) require_in_box({&a, &b, &c, &d, &e});
    const double value = detail::lifted_det4_negated(
        detail::lifted_differences<false>(a, b, c, d, e, 0, 0, 0, 0, 0).rows);
    const int f = detail::decide(value, insphere_bound_, std::fabs(value) <= kMaxFinite);
    if (f != detail::kUndecided) [[likely]] RSTRUCT_PREDICATE_COUNT(insphere, filter);
    return f;
  }

  /// insphere_filter, and where the box bound cannot decide, the semi-static bound of
  /// detail::insphere_filter applied to the same computed value: the two filters evaluate
  /// the same floating-point expression, so either bound certifies its sign. Small cells
  /// in a large box (dense samples, points on a surface, whose determinants fall below
  /// the box bound) are then decided without a second evaluation. Same results as
  /// insphere_filter where that decides; kUndecided only where both bounds fail.
  /// \pre as for orient3d.
  int insphere_filter_two_stage(const Point3& a, const Point3& b, const Point3& c,
                                const Point3& d, const Point3& e) const {
    if constexpr (check_level() >= 2) require_in_box({&a, &b, &c, &d, &e});
    return lifted_two_stage<false>(a, b, c, d, e, 0, 0, 0, 0, 0);
  }

  /// The power test's filter (detail::lifted4_filter_points<true>) in two stages as
  /// insphere_filter_two_stage: the static bound of set_weight_range (+inf before it is
  /// called), then the semi-static bound on the same computed value. −1 or +1, the sign
  /// of predicates::power_test, or kUndecided. \pre as for orient3d, and the weights lie
  /// in the range given to set_weight_range (if it was called).
  int power_test_filter_two_stage(const Point3& a, const Point3& b, const Point3& c,
                                  const Point3& d, const Point3& e, double aw, double bw,
                                  double cw, double dw, double ew) const {
    if constexpr (check_level() >= 2) {
      require_in_box({&a, &b, &c, &d, &e});
      if (power_test_bound_ != HUGE_VAL) {
        for (const double w : {aw, bw, cw, dw, ew}) {
          if (!(w >= wlo_ && w <= whi_)) {
            throw InvalidInput("AlmostStaticFilter: weight outside the filter's range");
          }
        }
      }
    }
    return lifted_two_stage<true>(a, b, c, d, e, aw, bw, cw, dw, ew);
  }

  /// The precomputed bounds (+inf: that filter never decides), for tests and reports.
  double orient3d_bound() const { return orient3d_bound_; }
  double insphere_bound() const { return insphere_bound_; }
  double power_test_bound() const { return power_test_bound_; }

 private:
  static constexpr double kMaxFinite = 0x1.fffffffffffffp1023;

  /// The two stages of insphere_filter_two_stage (kWeighted false: the weights are
  /// ignored) and power_test_filter_two_stage: the expressions of
  /// detail::lifted4_filter_points<kWeighted>, with the static bound tried first.
  /// Always inlined: the conflict search evaluates it for every cell it visits (left to
  /// itself, GCC stopped inlining it into the parallel passes' search: double torus on two
  /// threads 0.46 s, inlined 0.35 s).
  template <bool kWeighted>
#if defined(__GNUC__)
  __attribute__((always_inline))
#endif
  int lifted_two_stage(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                       const Point3& e, double aw, double bw, double cw, double dw,
                       double ew) const {
    const Point3 ta = a - e, tb = b - e, tc = c - e, td = d - e;
    double wa = 0, wb = 0, wc = 0, wd = 0;
    if constexpr (kWeighted) {
      wa = aw - ew, wb = bw - ew, wc = cw - ew, wd = dw - ew;
    } else {
      (void)aw, (void)bw, (void)cw, (void)dw, (void)ew;
    }
    using detail::lifted_height;
    const detail::LiftedRows<double> rows{
        ta.x, ta.y, ta.z, lifted_height(ta.x, ta.y, ta.z, wa),
        tb.x, tb.y, tb.z, lifted_height(tb.x, tb.y, tb.z, wb),
        tc.x, tc.y, tc.z, lifted_height(tc.x, tc.y, tc.z, wc),
        td.x, td.y, td.z, lifted_height(td.x, td.y, td.z, wd)};
    const double value = detail::lifted_det4_negated(rows);
    const double static_bound = kWeighted ? power_test_bound_ : insphere_bound_;
    int f = detail::decide(value, static_bound, std::fabs(value) <= kMaxFinite);
    if (f == detail::kUndecided) [[unlikely]] {
      const double mx = detail::abs_max4(ta.x, tb.x, tc.x, td.x);
      const double my = detail::abs_max4(ta.y, tb.y, tc.y, td.y);
      const double mz = detail::abs_max4(ta.z, tb.z, tc.z, td.z);
      const double big = detail::max2(detail::max2(mx, my), mz);
      const bool ok =
          detail::in_guard(detail::min3(mx, my, mz), value, detail::filter::kGuardDegree5);
      if constexpr (kWeighted) {
        const double mw = detail::abs_max4(wa, wb, wc, wd);
        f = detail::decide(
            value, detail::filter::kPowerTest * mx * my * mz * detail::max2(big * big, mw), ok);
      } else {
        f = detail::decide(value, detail::filter::kInsphere * mx * my * mz * (big * big), ok);
      }
    }
    if (f != detail::kUndecided) {
      if constexpr (kWeighted) {
        RSTRUCT_PREDICATE_COUNT(power_test, filter);
      } else {
        RSTRUCT_PREDICATE_COUNT(insphere, filter);
      }
    }
    return f;
  }

  void require_in_box(std::initializer_list<const Point3*> points) const {
    for (const Point3* p : points) {
      for (std::size_t i = 0; i < 3; ++i) {
        if (!((*p)[i] >= lo_[i] && (*p)[i] <= hi_[i])) {
          throw InvalidInput("AlmostStaticFilter: input point outside the filter's box (axis " +
                             std::to_string(i) + ")");
        }
      }
    }
  }

  Point3 lo_, hi_;
  double orient3d_bound_ = HUGE_VAL;
  double insphere_bound_ = HUGE_VAL;
  double power_test_bound_ = HUGE_VAL;
  double wlo_ = 0, whi_ = 0;
};

}  // namespace rstruct::predicates
