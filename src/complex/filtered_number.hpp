#pragma once
// A double that carries a certified bound on its rounding error, for the floating-point
// filter of the complex module's predicates (written here because the shared numeric
// facility had not landed; see the module note).
//
// Error model (Higham, "Accuracy and Stability of Numerical Algorithms", §3.1–3.4): an
// expression in + − × over exact double inputs, evaluated in IEEE binary64 with
// round-to-nearest and no fused operations (-ffp-contract=off), computes
//   ṽ = Σ_t t·(1 + θ_t),  |θ_t| ≤ γ_d = d·u / (1 − d·u),  u = 2⁻⁵³,
// where the sum runs over the monomials t of the fully expanded expression and d is the
// expression's *depth*: leaves 0, a ± b → max(d_a, d_b) + 1, a × b → d_a + d_b + 1. With
// M = Σ |t| (the same expression evaluated on |leaves| with − replaced by +), computed as
// M̃ ≥ M (1 − γ_d): |ṽ − exact| ≤ γ_d M ≤ γ_d M̃ / (1 − γ_d) < 2 d u M̃ (1 − u) for
// d ≤ 10⁶, so |ṽ| > fl(M̃ · d · 2⁻⁵²) certifies the sign (the last product rounds once,
// covered by the factor (1 − u)).
// The model assumes no underflow and no overflow: a product whose result is subnormal, or
// zero from non-zero factors, sets `unsafe`, and non-finite values fail the certificate.
// Sums never underflow harmfully (a subnormal sum of doubles is exact).

#include <algorithm>
#include <cmath>

namespace rstruct::complex::detail {

struct FilteredNumber {
  double v = 0;        // computed value
  double m = 0;        // computed magnitude M̃
  int d = 0;           // depth
  bool unsafe = false; // an underflow happened somewhere below

  FilteredNumber() = default;
  explicit FilteredNumber(double x) : v(x), m(std::fabs(x)) {}
  FilteredNumber(double value, double magnitude, int depth, bool u)
      : v(value), m(magnitude), d(depth), unsafe(u) {}

  friend FilteredNumber operator+(const FilteredNumber& a, const FilteredNumber& b) {
    return {a.v + b.v, a.m + b.m, std::max(a.d, b.d) + 1, a.unsafe || b.unsafe};
  }
  friend FilteredNumber operator-(const FilteredNumber& a, const FilteredNumber& b) {
    return {a.v - b.v, a.m + b.m, std::max(a.d, b.d) + 1, a.unsafe || b.unsafe};
  }
  friend FilteredNumber operator*(const FilteredNumber& a, const FilteredNumber& b) {
    const double v = a.v * b.v;
    const bool underflow = (v != 0 && std::fabs(v) < 0x1p-1022) ||
                           (v == 0 && a.v != 0 && b.v != 0);
    const double m = a.m * b.m;
    const bool m_underflow = (m != 0 && m < 0x1p-1022) || (m == 0 && a.m != 0 && b.m != 0);
    return {v, m, a.d + b.d + 1, a.unsafe || b.unsafe || underflow || m_underflow};
  }
  FilteredNumber& operator+=(const FilteredNumber& o) { return *this = *this + o; }
  FilteredNumber& operator-=(const FilteredNumber& o) { return *this = *this - o; }
  FilteredNumber& operator*=(const FilteredNumber& o) { return *this = *this * o; }

  /// a − b for two input doubles. If the rounded difference is exact (checked with
  /// Knuth's TwoSum: the rounding error of a + (−b) is computed exactly), it is a new exact
  /// leaf (depth 0, magnitude |a − b|), which is common for nearby points (Sterbenz).
  static FilteredNumber difference(double a, double b) {
    const double s = a - b;
    const double nb = -b;
    const double bb = s - a;
    const double err = (a - (s - bb)) + (nb - bb);
    if (err == 0 && std::isfinite(s)) return FilteredNumber(s);
    return {s, std::fabs(a) + std::fabs(b), 1, false};
  }

  /// A certified bound on |v − exact value| (the bound certified_sign compares with), or
  /// +infinity when the model does not hold (underflow, non-finite values).
  double error_bound() const {
    if (unsafe || !std::isfinite(v) || !std::isfinite(m)) return HUGE_VAL;
    const double bound = m * (static_cast<double>(d) * 0x1p-52);
    return std::isfinite(bound) ? bound : HUGE_VAL;
  }

  /// −1, 0 or +1 if the sign of the exact value is certified, else 2.
  int certified_sign() const {
    if (unsafe || !std::isfinite(v) || !std::isfinite(m)) return 2;
    if (m == 0) return 0;  // every monomial is exactly zero
    const double bound = m * (static_cast<double>(d) * 0x1p-52);
    if (!std::isfinite(bound)) return 2;
    if (v > bound) return 1;
    if (v < -bound) return -1;
    return 2;
  }
};

}  // namespace rstruct::complex::detail
