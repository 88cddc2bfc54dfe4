#pragma once
/// \file
/// Dynamic filter of the lifted 4×4 determinant (in-sphere and power tests): the stage
/// between the semi-static filter (filters.hpp) and the exact one. The semi-static bound
/// K·S uses the largest difference of each column for every entry, so it is loose for
/// long, thin cells, whose differences span several orders of magnitude; their values are
/// also small (10^6 points on a torus: 2.8 % of the conflict tests reached the exact stage,
/// none for 10^6 uniform points). This stage bounds the error by the permanent P̃ of the
/// same expression tree instead (filter_constants.hpp, kInsphereDynamic), which follows
/// the actual magnitudes of every term, at the price of a second evaluation: worth it only
/// where the cheaper filter failed.

#include <array>
#include <cmath>

#include "rstruct/geometry/vec3.hpp"
#include "rstruct/predicates/detail/filter_constants.hpp"
#include "rstruct/predicates/detail/filters.hpp"
#include "rstruct/predicates/detail/polynomials.hpp"

namespace rstruct::predicates::detail {

/// A non-negative double on which subtraction adds. A polynomial template of
/// polynomials.hpp evaluated on the absolute values of its leaves with this type gives
/// its permanent: every term of the expanded tree counted with a plus sign, computed
/// with the same operations in the same order as the value itself.
struct PermanentTerm {
  double v;
};
inline PermanentTerm operator+(PermanentTerm a, PermanentTerm b) { return {a.v + b.v}; }
inline PermanentTerm operator-(PermanentTerm a, PermanentTerm b) { return {a.v + b.v}; }
inline PermanentTerm operator*(PermanentTerm a, PermanentTerm b) { return {a.v * b.v}; }

/// Sign of −det[(p − e, |p − e|² − (w_p − w_e))] for p = a, b, c, d (the power test;
/// `weighted` false ignores the weights: insphere), or kUndecided when the dynamic bound
/// cannot certify it (also for non-finite input, which the exact stage reports).
template <bool weighted>
int lifted4_dynamic_filter(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                           const Point3& e, double aw, double bw, double cw, double dw,
                           double ew) {
  const auto [ta, tb, tc, td, wa, wb, wc, wd, rows] =
      lifted_differences<weighted>(a, b, c, d, e, aw, bw, cw, dw, ew);
  const double value = lifted_det4_negated(rows);
  const auto abs = [](double x) { return PermanentTerm{std::fabs(x)}; };
  const auto row = [&](const Point3& t, double w) {
    const PermanentTerm x = abs(t.x), y = abs(t.y), z = abs(t.z);
    return std::array<PermanentTerm, 4>{x, y, z, lifted_height(x, y, z, abs(w))};
  };
  const auto pa = row(ta, wa), pb = row(tb, wb), pc = row(tc, wc), pd = row(td, wd);
  const double permanent = lifted_det4_negated(LiftedRows<PermanentTerm>{
                               pa[0], pa[1], pa[2], pa[3], pb[0], pb[1], pb[2], pb[3],
                               pc[0], pc[1], pc[2], pc[3], pd[0], pd[1], pd[2], pd[3]})
                               .v;
  const double bound =
      (weighted ? filter::kPowerTestDynamic : filter::kInsphereDynamic) * permanent;
  const filter::DynamicGuard& g = filter::kGuardDynamic;
  const double m = max2(max2(abs_max4(ta.x, tb.x, tc.x, td.x), abs_max4(ta.y, tb.y, tc.y, td.y)),
                        abs_max4(ta.z, tb.z, tc.z, td.z));
  const bool ok = (m <= g.max_difference) & (abs_max4(wa, wb, wc, wd) <= g.max_weight_difference) &
                  (bound >= g.min_bound) & (std::fabs(value) <= 0x1.fffffffffffffp1023);
  return decide(value, bound, ok);
}

}  // namespace rstruct::predicates::detail
