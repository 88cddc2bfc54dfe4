#include "rstruct/predicates/detail/counting.hpp"
#include "predicates/exact_stage.hpp"
#include "rstruct/predicates/detail/filters.hpp"
#include "rstruct/predicates/predicates.hpp"

namespace rstruct::predicates {

Sign compare_squared_distance(const Point3& x, const Point3& p, const Point3& q) {
  const int f = detail::squared_distance_difference_filter(x, p, q);
  if (f != detail::kUndecided) {
    RSTRUCT_PREDICATE_COUNT(compare_squared_distance, filter);
    return static_cast<Sign>(f);
  }
  RSTRUCT_PREDICATE_COUNT(compare_squared_distance, exact);
  return static_cast<Sign>(detail::squared_distance_difference_exact(x, p, q));
}

Sign compare_power_distance(const Point3& x, const WeightedPoint& p, const WeightedPoint& q) {
  const int f = detail::power_difference_filter(x, p, q);
  if (f != detail::kUndecided) {
    RSTRUCT_PREDICATE_COUNT(compare_power_distance, filter);
    return static_cast<Sign>(f);
  }
  RSTRUCT_PREDICATE_COUNT(compare_power_distance, exact);
  return static_cast<Sign>(detail::power_difference_exact(x, p, q));
}

Sign power_sign(const Point3& x, const WeightedPoint& p) {
  const int f = detail::power_value_filter(x, p);
  if (f != detail::kUndecided) {
    RSTRUCT_PREDICATE_COUNT(power_sign, filter);
    return static_cast<Sign>(f);
  }
  RSTRUCT_PREDICATE_COUNT(power_sign, exact);
  return static_cast<Sign>(detail::power_value_exact(x, p));
}

Sign side_of_ball(const Point3& x, const Point3& c, double r) {
  const int f = detail::ball_side_filter(x, c, r);
  if (f != detail::kUndecided) {
    RSTRUCT_PREDICATE_COUNT(side_of_ball, filter);
    return static_cast<Sign>(f);
  }
  RSTRUCT_PREDICATE_COUNT(side_of_ball, exact);
  return static_cast<Sign>(detail::ball_side_exact(x, c, r));
}

}  // namespace rstruct::predicates
