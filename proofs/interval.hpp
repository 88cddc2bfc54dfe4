// Shared helpers of the proofs/ programs (issue 9): outward-rounded interval arithmetic over
// Boost.Multiprecision's MPFI backend, a claim reporter and an interval branch-and-bound.
//
// Every number a claim depends on is an Interval that is guaranteed to contain the true real
// value (MPFI rounds every operation outward). Decimal constants of the paper are built as
// exact ratios of integers (`ratio(9807, 10000)`), never parsed from binary doubles.
//
// Output of every program: one line per claim,
//   claim | enclosure | margin | HOLDS / FAILS / UNDECIDED
// and the exit status is 0 iff every claim HOLDS.
#pragma once

#include <mpfi.h>
#include <mpfr.h>

#include <boost/multiprecision/mpfi.hpp>
#include <cstdio>
#include <functional>
#include <iostream>
#include <limits>
#include <queue>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rstruct::proofs {

/// 80 decimal digits = 266 bits of working precision; every operation rounded outward.
using Interval = boost::multiprecision::number<boost::multiprecision::mpfi_float_backend<80>,
                                               boost::multiprecision::et_off>;
using Real = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<80>,
                                           boost::multiprecision::et_off>;

/// Enclosure of the rational a / b.
inline Interval ratio(long a, long b) { return Interval(a) / Interval(b); }
/// The interval [lo, hi] (lo <= hi, both exact doubles).
inline Interval hull(double lo, double hi) { return Interval(lo, hi); }
inline Interval hull(const Interval& a, const Interval& b) {
  return boost::multiprecision::hull(a, b);
}
inline Interval pi() { return boost::math::constants::pi<Interval>(); }
/// Degrees to radians.
inline Interval deg(const Interval& d) { return d * pi() / 180; }
inline Interval deg(long d) { return deg(Interval(d)); }
/// Radians to degrees.
inline Interval to_deg(const Interval& rad) { return rad * 180 / pi(); }

inline Real lo(const Interval& x) { return boost::multiprecision::lower(x); }
inline Real hi(const Interval& x) { return boost::multiprecision::upper(x); }
inline double lo_d(const Interval& x) {  // rounded down
  return mpfr_get_d(boost::multiprecision::lower(x).backend().data(), MPFR_RNDD);
}
inline double hi_d(const Interval& x) {  // rounded up
  return mpfr_get_d(boost::multiprecision::upper(x).backend().data(), MPFR_RNDU);
}
inline double mid_d(const Interval& x) { return 0.5 * lo_d(x) + 0.5 * hi_d(x); }
inline bool is_nan(const Interval& x) { return mpfi_nan_p(x.backend().data()) != 0; }

/// sqrt of a quantity that is mathematically >= 0: the enclosure's negative part (an
/// artefact of dependency in interval evaluation) is cut off first.
inline Interval sqrt_nonneg(const Interval& x) {
  if (hi(x) < 0) throw std::domain_error("sqrt_nonneg: argument certainly negative");
  Interval y = x;
  if (lo(y) < 0) y = Interval(Real(0), hi(y));
  return boost::multiprecision::sqrt(y);
}
/// Clamp an enclosure of a quantity mathematically in [-1, 1] (a cosine or sine).
inline Interval clamp_unit(const Interval& x) {
  if (hi(x) < -1 || lo(x) > 1) throw std::domain_error("clamp_unit: outside [-1, 1]");
  Real l = lo(x) < -1 ? Real(-1) : lo(x);
  Real h = hi(x) > 1 ? Real(1) : hi(x);
  return Interval(l, h);
}
inline Interval asin_u(const Interval& x) { return boost::multiprecision::asin(clamp_unit(x)); }
inline Interval acos_u(const Interval& x) { return boost::multiprecision::acos(clamp_unit(x)); }
inline Interval max(const Interval& a, const Interval& b) {
  return Interval(lo(a) > lo(b) ? lo(a) : lo(b), hi(a) > hi(b) ? hi(a) : hi(b));
}
inline Interval min(const Interval& a, const Interval& b) {
  return Interval(lo(a) < lo(b) ? lo(a) : lo(b), hi(a) < hi(b) ? hi(a) : hi(b));
}

/// Text of an enclosure, its ends rounded outward to `digits` significant digits.
inline std::string str(const Interval& x, int digits = 10) {
  if (is_nan(x)) return "[NaN]";
  char a[96];
  char b[96];
  mpfr_snprintf(a, sizeof a, "%.*RDg", digits, boost::multiprecision::lower(x).backend().data());
  mpfr_snprintf(b, sizeof b, "%.*RUg", digits, boost::multiprecision::upper(x).backend().data());
  return std::string("[") + a + ", " + b + "]";
}
/// Lower end of an enclosure rounded down (a certified lower bound), as text.
inline std::string str_lo(const Interval& x, int digits = 4) {
  char a[96];
  mpfr_snprintf(a, sizeof a, "%.*RDg", digits, boost::multiprecision::lower(x).backend().data());
  return a;
}

enum class Verdict { kHolds, kFails, kUndecided };
inline const char* verdict_name(Verdict v) {
  return v == Verdict::kHolds ? "HOLDS" : v == Verdict::kFails ? "FAILS" : "UNDECIDED";
}

/// Result of a branch-and-bound: a certified enclosure [lower, upper] of the extremum, or a
/// counterexample point.
struct BnbResult {
  Interval extremum;          ///< contains the true minimum (or maximum) over the region
  std::vector<double> point;  ///< a feasible point whose value attains the upper (lower) end
  long boxes = 0;             ///< boxes evaluated
  bool converged = false;     ///< false: budget exhausted, extremum is still a valid enclosure
};

/// Evaluation of an objective on a box: `value` encloses f over the feasible points of the
/// box; `feasible` says whether all / none / some of the box satisfies the constraints.
enum class Feasible { kAll, kNone, kSome };
struct Eval {
  Interval value;
  Feasible feasible = Feasible::kAll;
};
using Box = std::vector<Interval>;
using Objective = std::function<Eval(const Box&)>;

/// Rigorous interval branch-and-bound for min f over the feasible part of `box`. Boxes are
/// bisected along their widest coordinate (widths measured relative to `scale`, one entry
/// per coordinate). Stops when upper - lower <= tol, when no box is left, or after
/// max_boxes evaluations. The returned enclosure always contains the true minimum (if the
/// feasible set is non-empty); `point` is the best feasible midpoint found. `witness`, if
/// given, encloses f at a feasible point known to the caller (e.g. the paper's extreme
/// configuration): it seeds the upper bound, so boxes that cannot beat it are pruned at once.
/// `prove_above`: stop as soon as every remaining box has f > prove_above (the claim
/// "min f > prove_above" is then proved; the enclosure's lower end is > prove_above).
inline BnbResult minimize(const Objective& f, const Box& box, double tol, long max_boxes,
                          std::vector<double> scale = {}, const Interval* witness = nullptr,
                          double prove_above = std::numeric_limits<double>::infinity()) {
  if (scale.empty()) scale.assign(box.size(), 1.0);
  struct Node {
    double key;
    Box box;
    Interval value;
    bool operator<(const Node& o) const { return key > o.key; }  // min-heap on key
  };
  std::priority_queue<Node> queue;
  BnbResult result;
  Real best_upper = std::numeric_limits<double>::infinity();
  if (witness != nullptr) best_upper = hi(*witness);
  auto try_midpoint = [&](const Box& b) {
    Box mid;
    std::vector<double> pt;
    for (const auto& c : b) {
      pt.push_back(mid_d(c));
      mid.emplace_back(pt.back());
    }
    Eval e = f(mid);
    ++result.boxes;
    if (e.feasible == Feasible::kAll && hi(e.value) < best_upper) {
      best_upper = hi(e.value);
      result.point = pt;
    }
  };
  Real min_discarded = std::numeric_limits<double>::infinity();  // lower ends of pruned boxes
  auto push = [&](Box b) {
    Eval e = f(b);
    ++result.boxes;
    if (e.feasible == Feasible::kNone) return;
    if (lo(e.value) > best_upper) {
      if (lo(e.value) < min_discarded) min_discarded = lo(e.value);
      return;
    }
    queue.push(Node{lo_d(e.value), std::move(b), e.value});
  };
  push(box);
  Real lower = std::numeric_limits<double>::infinity();
  while (!queue.empty()) {
    Node n = queue.top();
    queue.pop();
    if (lo(n.value) > best_upper) {
      if (lo(n.value) < min_discarded) min_discarded = lo(n.value);
      continue;
    }
    if (n.key > prove_above) {  // n has the smallest key: every remaining box is above
      lower = Real(n.key);
      result.converged = true;
      break;
    }
    try_midpoint(n.box);
    if (best_upper - lo(n.value) <= tol || result.boxes >= max_boxes) {
      lower = Real(n.key);  // every queued box has key >= n.key: a global lower bound
      result.converged = result.boxes < max_boxes;
      break;
    }
    size_t k = 0;
    double widest = -1;
    for (size_t i = 0; i < n.box.size(); ++i) {
      double w = (hi_d(n.box[i]) - lo_d(n.box[i])) / scale[i];
      if (w > widest) widest = w, k = i;
    }
    double m = mid_d(n.box[k]);
    Box left = n.box;
    Box right = n.box;
    left[k] = Interval(lo(n.box[k]), Real(m));
    right[k] = Interval(Real(m), hi(n.box[k]));
    push(std::move(left));
    push(std::move(right));
  }
  if (queue.empty() && lower == std::numeric_limits<double>::infinity()) {
    // Every box was infeasible or pruned: with a witness, the witness is optimal up to
    // rounding; without one, the feasible set is empty (the enclosure is [+inf, +inf]).
    // Every feasible point lies in a pruned box: the minimum is >= the smallest lower end of
    // a pruned box (and <= best_upper).
    lower = min_discarded < best_upper ? min_discarded : best_upper;
    result.converged = true;
  }
  if (best_upper == std::numeric_limits<double>::infinity()) best_upper = lower;
  result.extremum = Interval(lower, best_upper > lower ? best_upper : lower);
  return result;
}

/// max f = -min(-f).
inline BnbResult maximize(const Objective& f, const Box& box, double tol, long max_boxes,
                          std::vector<double> scale = {}, const Interval* witness = nullptr) {
  Objective neg = [&f](const Box& b) {
    Eval e = f(b);
    e.value = -e.value;
    return e;
  };
  Interval neg_witness = witness != nullptr ? Interval(-*witness) : Interval(0);
  BnbResult r = minimize(neg, box, tol, max_boxes, std::move(scale),
                         witness != nullptr ? &neg_witness : nullptr);
  r.extremum = -r.extremum;
  return r;
}

/// Collects claims, prints one line each and the final verdict.
class Proof {
 public:
  explicit Proof(std::string title) {
    std::cout << "== " << title << "\n"
              << "claim | enclosure | margin | verdict\n";
  }

  /// value < bound (strict). Margin = bound - value.
  Verdict less(const std::string& claim, const Interval& value, const Interval& bound) {
    Interval margin = bound - value;
    Verdict v = lo(margin) > 0    ? Verdict::kHolds
                : hi(margin) <= 0 ? Verdict::kFails
                                  : Verdict::kUndecided;
    return record(claim, value, margin, v);
  }
  /// value <= bound.
  Verdict less_eq(const std::string& claim, const Interval& value, const Interval& bound) {
    Interval margin = bound - value;
    Verdict v = lo(margin) >= 0  ? Verdict::kHolds
                : hi(margin) < 0 ? Verdict::kFails
                                 : Verdict::kUndecided;
    return record(claim, value, margin, v);
  }
  /// value > bound (strict). Margin = value - bound.
  Verdict greater(const std::string& claim, const Interval& value, const Interval& bound) {
    Interval margin = value - bound;
    Verdict v = lo(margin) > 0    ? Verdict::kHolds
                : hi(margin) <= 0 ? Verdict::kFails
                                  : Verdict::kUndecided;
    return record(claim, value, margin, v);
  }
  Verdict greater_eq(const std::string& claim, const Interval& value, const Interval& bound) {
    Interval margin = value - bound;
    Verdict v = lo(margin) >= 0  ? Verdict::kHolds
                : hi(margin) < 0 ? Verdict::kFails
                                 : Verdict::kUndecided;
    return record(claim, value, margin, v);
  }
  /// A derived fact that is printed for information (no verdict).
  void note(const std::string& what, const Interval& value) {
    std::cout << "  info: " << what << " | " << str(value) << "\n";
  }
  void note(const std::string& what) { std::cout << "  info: " << what << "\n"; }

  int finish() const {
    std::cout << "== " << holds_ << " HOLDS, " << fails_ << " FAILS, " << undecided_
              << " UNDECIDED\n";
    return (fails_ == 0 && undecided_ == 0) ? 0 : 1;
  }

 private:
  Verdict record(const std::string& claim, const Interval& value, const Interval& margin,
                 Verdict v) {
    if (is_nan(value) || is_nan(margin)) v = Verdict::kUndecided;
    std::cout << claim << " | " << str(value) << " | " << str_lo(margin, 4) << " | "
              << verdict_name(v) << "\n";
    (v == Verdict::kHolds ? holds_ : v == Verdict::kFails ? fails_ : undecided_)++;
    return v;
  }
  int holds_ = 0;
  int fails_ = 0;
  int undecided_ = 0;
};

}  // namespace rstruct::proofs
