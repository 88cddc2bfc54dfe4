#pragma once
/// \file
/// Exact conversion of doubles to integers at a common binary scale, the entry to the
/// exact stage. Every finite double is m·2^k with an odd integer m (or zero); for a unit
/// 2^s with s ≤ k, x / 2^s is an integer. Choosing s as the smallest such k among the
/// inputs of one predicate call makes all of them integers; weights live at scale 2^(2s)
/// so that |p − e|² − w is homogeneous. Differences and products of these integers are
/// then exact in GMP, whatever the exponents (subnormals included).

#include <gmpxx.h>

#include <algorithm>
#include <bit>
#include <climits>
#include <cstdint>

#include "rstruct/numeric/bounded_int.hpp"

namespace rstruct::predicates::detail {

/// x = mantissa · 2^exponent with mantissa odd, or mantissa = 0 for x = 0.
struct DyadicParts {
  std::int64_t mantissa = 0;
  int exponent = 0;
};

/// Splits a finite double exactly (subnormals included). \pre std::isfinite(x).
inline DyadicParts split_double(double x) {
  const auto bits = std::bit_cast<std::uint64_t>(x);
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  std::uint64_t m = bits & ((std::uint64_t{1} << 52) - 1);
  int e = -1074;
  if (biased != 0) {
    m |= std::uint64_t{1} << 52;
    e = biased - 1075;
  }
  if (m == 0) return {};
  const int tz = std::countr_zero(m);
  m >>= tz;
  const auto signed_m = static_cast<std::int64_t>(m);
  return {(bits >> 63) != 0 ? -signed_m : signed_m, e + tz};
}

/// Exponent just above the highest set bit of a non-zero split double.
inline int top_exponent(const DyadicParts& p) {
  const auto m = static_cast<std::uint64_t>(p.mantissa < 0 ? -p.mantissa : p.mantissa);
  return p.exponent + static_cast<int>(std::bit_width(m));
}

/// The common unit exponent s of one predicate call, and bit lengths for the choice
/// between BoundedInt and GMP.
class ScaleFinder {
 public:
  /// A coordinate: s ≤ its lowest set bit.
  void add_coordinate(double x) {
    const DyadicParts p = split_double(x);
    if (p.mantissa == 0) return;
    unit_ = std::min(unit_, p.exponent);
    top_coordinate_ = std::max(top_coordinate_, top_exponent(p));
  }
  /// A weight (an area): 2s ≤ its lowest set bit.
  void add_weight(double w) {
    const DyadicParts p = split_double(w);
    if (p.mantissa == 0) return;
    const int half = p.exponent >= 0 ? p.exponent / 2 : -((-p.exponent + 1) / 2);
    unit_ = std::min(unit_, half);
    top_weight_ = std::max(top_weight_, top_exponent(p));
  }
  /// s (0 if every input was zero).
  int unit() const { return unit_ == INT_MAX ? 0 : unit_; }
  /// Bits of any difference of two scaled coordinates (at least 1).
  int coordinate_difference_bits() const {
    return top_coordinate_ == INT_MIN ? 1 : top_coordinate_ - unit() + 1;
  }
  /// Bits of any difference of two scaled weights (at least 1).
  int weight_difference_bits() const {
    return top_weight_ == INT_MIN ? 1 : top_weight_ - 2 * unit() + 1;
  }
  /// Bits of a lifting height |t|² − (w_p − w_e) (three squares and a weight difference).
  int lifted_height_bits() const {
    return std::max(2 * coordinate_difference_bits() + 2, weight_difference_bits()) + 1;
  }

 private:
  int unit_ = INT_MAX;
  int top_coordinate_ = INT_MIN;
  int top_weight_ = INT_MIN;
};

/// out = x / 2^unit, exactly. \pre x finite and 2^unit divides x.
inline void set_scaled(mpz_class& out, double x, int unit) {
  const DyadicParts p = split_double(x);
  out = static_cast<long>(p.mantissa);
  if (p.mantissa != 0) {
    mpz_mul_2exp(out.get_mpz_t(), out.get_mpz_t(),
                 static_cast<mp_bitcnt_t>(p.exponent - unit));
  }
}

/// out = x / 2^unit, exactly, as a BoundedInt. \pre as above, and the result fits.
template <int N>
void set_scaled(numeric::BoundedInt<N>& out, double x, int unit) {
  const DyadicParts p = split_double(x);
  const auto m = static_cast<std::uint64_t>(p.mantissa < 0 ? -p.mantissa : p.mantissa);
  out.assign_shifted(m, p.mantissa != 0 ? p.exponent - unit : 0, p.mantissa < 0);
}

/// Sign of an exact integer as an int.
inline int sign_int(const mpz_class& v) { return mpz_sgn(v.get_mpz_t()); }
template <int N>
int sign_int(const numeric::BoundedInt<N>& v) {
  return v.sign();
}

/// The BoundedInt of the fast exact stage: 6 limbs, enough for the 5th-degree in-sphere
/// determinant of inputs whose scaled differences have up to ~75 bits (nearby doubles).
using FastInt = numeric::BoundedInt<6>;

/// A wider inline integer for orient3d with per-column scales: 1280 bits cover one column
/// spanning the whole double range (subnormal to 1) next to two ordinary columns.
using WideInt = numeric::BoundedInt<20>;

}  // namespace rstruct::predicates::detail
