#pragma once
/// \file
/// Interval: a closed interval [lo, hi] of doubles with guaranteed outward rounding, the
/// first stage of numeric::filtered_sign. Each operation rounds to nearest (the default
/// mode; no fesetround) and then moves each bound one ulp outward: a correctly rounded
/// result is within half an ulp of the exact one (within 2⁻¹⁰⁷⁵ on underflow, less than
/// the subnormal step 2⁻¹⁰⁷⁴), so the widened interval encloses the exact result of the
/// operation on any points of the operand intervals. Overflow gives infinite bounds, an
/// undefined operation (∞ − ∞, 0·∞) gives NaN bounds; both make sign() undecided.
/// Only +, − and × are provided: write predicates as polynomials.

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "rstruct/predicates/sign.hpp"

namespace rstruct::numeric {

/// The next double above x (x itself for +inf and NaN).
inline double next_up(double x) {
  if (std::isnan(x) || x == std::numeric_limits<double>::infinity()) return x;
  if (x == 0) return std::numeric_limits<double>::denorm_min();
  const auto bits = std::bit_cast<std::uint64_t>(x);
  return std::bit_cast<double>(x > 0 ? bits + 1 : bits - 1);
}

/// The next double below x (x itself for −inf and NaN).
inline double next_down(double x) { return -next_up(-x); }

class Interval {
 public:
  Interval() = default;
  /// The exact point interval [x, x].
  Interval(double x) : lo_(x), hi_(x) {}  // NOLINT(google-explicit-constructor): numeric type
  /// [lo, hi]. \pre lo <= hi.
  Interval(double lo, double hi) : lo_(lo), hi_(hi) {}

  double lower() const { return lo_; }
  double upper() const { return hi_; }
  /// True iff x lies in the interval.
  bool contains(double x) const { return lo_ <= x && x <= hi_; }

  /// The sign of every point of the interval, or nullopt if it is not the same for all
  /// (or a bound is NaN).
  std::optional<Sign> sign() const {
    if (lo_ > 0) return Sign::positive;
    if (hi_ < 0) return Sign::negative;
    if (lo_ == 0 && hi_ == 0) return Sign::zero;
    return std::nullopt;
  }

  friend Interval operator-(const Interval& a) { return {-a.hi_, -a.lo_}; }
  friend Interval operator+(const Interval& a, const Interval& b) {
    return {next_down(a.lo_ + b.lo_), next_up(a.hi_ + b.hi_)};
  }
  friend Interval operator-(const Interval& a, const Interval& b) {
    return {next_down(a.lo_ - b.hi_), next_up(a.hi_ - b.lo_)};
  }
  friend Interval operator*(const Interval& a, const Interval& b) {
    const double p1 = a.lo_ * b.lo_, p2 = a.lo_ * b.hi_, p3 = a.hi_ * b.lo_, p4 = a.hi_ * b.hi_;
    if (std::isnan(p1) || std::isnan(p2) || std::isnan(p3) || std::isnan(p4)) {
      const double nan = std::numeric_limits<double>::quiet_NaN();
      return {nan, nan};
    }
    return {next_down(std::fmin(std::fmin(p1, p2), std::fmin(p3, p4))),
            next_up(std::fmax(std::fmax(p1, p2), std::fmax(p3, p4)))};
  }
  Interval& operator+=(const Interval& b) { return *this = *this + b; }
  Interval& operator-=(const Interval& b) { return *this = *this - b; }
  Interval& operator*=(const Interval& b) { return *this = *this * b; }

 private:
  double lo_ = 0, hi_ = 0;
};

}  // namespace rstruct::numeric
