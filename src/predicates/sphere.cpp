#include <array>
#include <string>

#include "rstruct/predicates/detail/counting.hpp"
#include "predicates/exact_stage.hpp"
#include "rstruct/predicates/detail/dynamic_filter.hpp"
#include "rstruct/predicates/detail/filters.hpp"
#include "predicates/perturbation.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/predicates/predicates.hpp"

namespace rstruct::predicates {
namespace {

/// Sign of the perturbed predicate when the unperturbed one is zero. The predicate is
/// −det[(p, |p|² − w_p, 1)] (rows p_0..p_4 = a..e); lowering height k by ε^(id_k+1) adds
/// ε^(id_k+1) times the cofactor of that height in det, which is (−1)^k times the
/// orientation of the other four points in order. The first non-zero one in id order
/// decides.
Sign perturbed_lifted4(const std::array<const Point3*, 5>& p,
                       const std::array<std::uint32_t, 5>& ids, const char* where) {
  for (const int k : detail::perturbation_order(ids, where)) {
    std::array<const Point3*, 4> q{};
    for (int i = 0, j = 0; i < 5; ++i) {
      if (i != k) q[static_cast<std::size_t>(j++)] = p[static_cast<std::size_t>(i)];
    }
    const Sign o = orient3d(*q[0], *q[1], *q[2], *q[3]);
    if (o != Sign::zero) return k % 2 == 0 ? o : -o;
  }
  throw InvalidInput(std::string("predicates::") + where +
                     ": the cell a, b, c, d is flat (precondition orient3d != 0)");
}

}  // namespace

// The filter stage of each predicate is inline in predicates.hpp; these are the stages
// after it, out of line: the dynamic filter (dynamic_filter.hpp), then the exact stage,
// then the perturbation.
namespace detail {
namespace {

/// The dynamic filter's sign of the in-sphere test, or kUndecided.
int insphere_dynamic(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                     const Point3& e) {
  const int f = lifted4_dynamic_filter<false>(a, b, c, d, e, 0, 0, 0, 0, 0);
  if (f != kUndecided) RSTRUCT_PREDICATE_COUNT(insphere, dynamic);
  return f;
}

/// The dynamic filter's sign of the power test, or kUndecided.
int power_test_dynamic(const WeightedPoint& a, const WeightedPoint& b, const WeightedPoint& c,
                       const WeightedPoint& d, const WeightedPoint& e) {
  const int f = lifted4_dynamic_filter<true>(a.c, b.c, c.c, d.c, e.c, a.w, b.w, c.w, d.w, e.w);
  if (f != kUndecided) RSTRUCT_PREDICATE_COUNT(power_test, dynamic);
  return f;
}

}  // namespace

Sign insphere_after_filter(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                           const Point3& e) {
  if (const int f = insphere_dynamic(a, b, c, d, e); f != kUndecided) return static_cast<Sign>(f);
  RSTRUCT_PREDICATE_COUNT(insphere, exact);
  return static_cast<Sign>(lifted4_exact({a, 0}, {b, 0}, {c, 0}, {d, 0}, {e, 0}));
}

Sign power_test_after_filter(const WeightedPoint& a, const WeightedPoint& b,
                             const WeightedPoint& c, const WeightedPoint& d,
                             const WeightedPoint& e) {
  if (const int f = power_test_dynamic(a, b, c, d, e); f != kUndecided) {
    return static_cast<Sign>(f);
  }
  RSTRUCT_PREDICATE_COUNT(power_test, exact);
  return static_cast<Sign>(lifted4_exact(a, b, c, d, e));
}

Sign insphere_sos_after_filter(const Point3& a, const Point3& b, const Point3& c,
                               const Point3& d, const Point3& e, std::uint32_t ia,
                               std::uint32_t ib, std::uint32_t ic, std::uint32_t id,
                               std::uint32_t ie) {
  if (const int f = insphere_dynamic(a, b, c, d, e); f != kUndecided) return static_cast<Sign>(f);
  const int s = lifted4_exact({a, 0}, {b, 0}, {c, 0}, {d, 0}, {e, 0});
  if (s != 0) {
    RSTRUCT_PREDICATE_COUNT(insphere, exact);
    return static_cast<Sign>(s);
  }
  RSTRUCT_PREDICATE_COUNT(insphere, perturbed);
  return perturbed_lifted4({&a, &b, &c, &d, &e}, {ia, ib, ic, id, ie}, "insphere_sos");
}

Sign power_test_sos_after_filter(const WeightedPoint& a, const WeightedPoint& b,
                                 const WeightedPoint& c, const WeightedPoint& d,
                                 const WeightedPoint& e, std::uint32_t ia, std::uint32_t ib,
                                 std::uint32_t ic, std::uint32_t id, std::uint32_t ie) {
  if (const int f = power_test_dynamic(a, b, c, d, e); f != kUndecided) {
    return static_cast<Sign>(f);
  }
  const int s = lifted4_exact(a, b, c, d, e);
  if (s != 0) {
    RSTRUCT_PREDICATE_COUNT(power_test, exact);
    return static_cast<Sign>(s);
  }
  RSTRUCT_PREDICATE_COUNT(power_test, perturbed);
  return perturbed_lifted4({&a.c, &b.c, &c.c, &d.c, &e.c}, {ia, ib, ic, id, ie},
                           "power_test_sos");
}

}  // namespace detail
}  // namespace rstruct::predicates
