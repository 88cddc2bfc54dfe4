#pragma once
// The first, cheap stage of the orthosphere predicates' filter: the error model of
// FilteredNumber (filtered_number.hpp; Higham §3.1–3.4) with the per-operation underflow
// tests replaced by one test on the leaves, and the differences of input doubles taken as
// rounded leaves. A sign it cannot certify goes to FilteredNumber, then to GMP.
//
// Leaves. A difference a − b of input doubles is the leaf e = a − b (a real number),
// computed as ẽ = fl(a − b) = e (1 + δ), |δ| ≤ u: one rounding, so the leaf has depth 1
// (also when the subtraction happens to be exact: a larger depth only enlarges the bound)
// and magnitude |ẽ|. Input doubles used as they are (w₀, the constant 4) have depth 0.
// The magnitude M̃ is evaluated by the same tree on |ẽ|, so the rounding of a leaf
// enters value and magnitude alike: ṽ = Σ_t t(e)(1 + θ_t) and M̃ = Σ_t |t(e)|(1 + θ'_t),
// |θ_t|, |θ'_t| ≤ γ_d, with the monomials t taken in the leaves e. Hence
// |ṽ − v| ≤ γ_d M ≤ γ_d M̃ / (1 − γ_d) < 2 d u M̃ (1 − u) exactly as in FilteredNumber
// (whose leaves are the input doubles; an inexact difference costs it |a| + |b|, here |ẽ|).
//
// No underflow (the model's assumption), from the leaves alone (kMinLeaf). Let every leaf
// ℓ̃ (a double) be 0 or have |ℓ̃| ≥ 2⁻⁷⁵; then ℓ̃ is an integer multiple of q = 2⁻¹²⁷ (its
// exponent is ≥ −75, its ulp ≥ 2⁻⁷⁵⁻⁵² = q). By induction over the tree, a node whose
// polynomial has degree ≤ t in the leaves is computed as an integer multiple of q^t: a sum
// of multiples of q^s and q^t (s ≤ t) is a multiple of q^t, a product of multiples of
// q^s and q^t one of q^(s+t); rounding to nearest maps a multiple m·Q of a power of two
// Q ≥ 2⁻¹⁰⁷⁴ to itself when |m| < 2⁵³ and otherwise onto a grid of spacing ulp ≥ Q, a power
// of two, so to a multiple of Q again. Every polynomial here has degree ≤ 8 in the leaves
// (|v|² in power() for k = 3; see kMaxDegree), so every non-zero exact product is a
// non-zero multiple of q^8 = 2⁻¹⁰¹⁶ ≥ 2⁻¹⁰²² and never lies in the subnormal range: each
// rounding is relative. (Sums never underflow harmfully.) The last product M̃ · d · 2⁻⁵²
// is kept normal by requiring M̃ ≥ 2⁻⁹⁶⁰ (d ≥ 1, so the product is ≥ 2⁻¹⁰¹²; with d = 0 the
// bound is 0 and the value exact). M̃ = 0 means every monomial is 0 (no product
// underflowed), so the value is exactly 0.
// No overflow: rounding is monotone, so |ṽ_p| ≤ M̃_p at every node; an overflow anywhere
// makes M̃ infinite or NaN (∞ · 0), and then `v > bound` and `v < −bound` are both false.

#include <cmath>

namespace rstruct::complex::detail {

#if defined(__GNUC__)
#define RSTRUCT_COMPLEX_INLINE inline __attribute__((always_inline))
#else
#define RSTRUCT_COMPLEX_INLINE inline
#endif

struct RoundedLeafNumber {
  /// Leaves below this magnitude (other than 0) send the call to the next stage.
  static constexpr double kMinLeaf = 0x1p-75;
  /// The largest degree in the leaves of any expression evaluated with this type (the
  /// bound kMinLeaf depends on it: 8 · (75 + 52) ≤ 1022).
  static constexpr int kMaxDegree = 8;
  static_assert(kMaxDegree * (75 + 52) <= 1022);

  double v = 0;  // computed value
  double m = 0;  // computed magnitude M̃
  int d = 0;     // depth

  RoundedLeafNumber() = default;
  RSTRUCT_COMPLEX_INLINE explicit RoundedLeafNumber(double x) : v(x), m(std::fabs(x)) {}
  RSTRUCT_COMPLEX_INLINE RoundedLeafNumber(double value, double magnitude, int depth)
      : v(value), m(magnitude), d(depth) {}

  friend RSTRUCT_COMPLEX_INLINE RoundedLeafNumber operator+(const RoundedLeafNumber& a,
                                                            const RoundedLeafNumber& b) {
    return {a.v + b.v, a.m + b.m, (a.d > b.d ? a.d : b.d) + 1};
  }
  friend RSTRUCT_COMPLEX_INLINE RoundedLeafNumber operator-(const RoundedLeafNumber& a,
                                                            const RoundedLeafNumber& b) {
    return {a.v - b.v, a.m + b.m, (a.d > b.d ? a.d : b.d) + 1};
  }
  friend RSTRUCT_COMPLEX_INLINE RoundedLeafNumber operator*(const RoundedLeafNumber& a,
                                                            const RoundedLeafNumber& b) {
    return {a.v * b.v, a.m * b.m, a.d + b.d + 1};
  }
  RSTRUCT_COMPLEX_INLINE RoundedLeafNumber& operator+=(const RoundedLeafNumber& o) {
    return *this = *this + o;
  }
  RSTRUCT_COMPLEX_INLINE RoundedLeafNumber& operator-=(const RoundedLeafNumber& o) {
    return *this = *this - o;
  }

  /// The rounded leaf fl(a − b) (depth 1, see above).
  static RSTRUCT_COMPLEX_INLINE RoundedLeafNumber difference(double a, double b) {
    const double s = a - b;
    return {s, std::fabs(s), 1};
  }

  /// Whether a leaf satisfies the no-underflow condition (0 or |x| ≥ kMinLeaf). NaN fails.
  static RSTRUCT_COMPLEX_INLINE bool is_safe_leaf(double x) {
    return x == 0 || std::fabs(x) >= kMinLeaf;
  }

  /// −1, 0 or +1 if the sign of the exact value is certified, else 2. \pre every leaf of
  /// the expression passed is_safe_leaf and its degree is at most kMaxDegree.
  RSTRUCT_COMPLEX_INLINE int certified_sign() const {
    if (m == 0) return 0;
    if (!(m >= 0x1p-960)) return 2;  // keeps the bound's product normal (NaN: fails)
    const double bound = m * (static_cast<double>(d) * 0x1p-52);
    if (v > bound) return 1;
    if (v < -bound) return -1;
    return 2;
  }
};

}  // namespace rstruct::complex::detail
