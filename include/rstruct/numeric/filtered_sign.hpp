#pragma once
/// \file
/// filtered_sign: the exact sign of a polynomial in doubles, written once as a generic
/// lambda and evaluated first in outward-rounded intervals (numeric::Interval), then, only
/// if the interval contains zero, exactly (numeric::Dyadic). This is the generic facility
/// for predicates of later stages (dual-complex "attached" tests, orthocentre-in-face
/// tests, medial-axis classification) that do not deserve a hand-derived static filter:
/// correct by construction, a few times slower than a static filter on the fast path.
///
/// Example (the sign of det[b − a; c − a] in 2D):
/// \code
///   Sign s = numeric::filtered_sign([](auto ax, auto ay, auto bx, auto by, auto cx, auto cy) {
///     return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
///   }, a.x, a.y, b.x, b.y, c.x, c.y);
/// \endcode
/// The lambda must use only +, − and × on its arguments (and on values built from them);
/// it is called with every argument of type Interval, then of type Dyadic, and must
/// return that type.
/// \throws rstruct::InvalidInput if an argument is NaN or infinite and the interval stage
/// could not decide.

#include <cstdint>

#include "rstruct/numeric/dyadic.hpp"
#include "rstruct/numeric/interval.hpp"
#include "rstruct/predicates/sign.hpp"

namespace rstruct::numeric {

/// How often each stage of filtered_sign decided (pass one to filtered_sign to count).
struct FilteredSignStats {
  std::uint64_t interval = 0;
  std::uint64_t exact = 0;
};

template <class F, class... Args>
Sign filtered_sign(FilteredSignStats* stats, const F& f, const Args&... args) {
  const Interval approx = f(Interval(static_cast<double>(args))...);
  if (const auto s = approx.sign()) {
    if (stats != nullptr) ++stats->interval;
    return *s;
  }
  if (stats != nullptr) ++stats->exact;
  return f(Dyadic(static_cast<double>(args))...).sign();
}

template <class F, class... Args>
Sign filtered_sign(const F& f, const Args&... args) {
  return filtered_sign(static_cast<FilteredSignStats*>(nullptr), f, args...);
}

}  // namespace rstruct::numeric
