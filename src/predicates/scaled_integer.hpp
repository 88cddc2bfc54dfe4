#pragma once
/// \file
/// Exact conversion of doubles to integers at a common binary scale, the entry to the
/// exact stage. Every finite double is m·2^k with an odd integer m (or zero); for a unit
/// 2^s with s ≤ k, x / 2^s is an integer. Choosing s as the smallest such k among the
/// inputs of one predicate call makes all of them integers; weights live at scale 2^(2s)
/// so that |p − e|² − w is homogeneous. Differences and products of these integers are
/// then exact in GMP, whatever the exponents (subnormals included).

#include <gmpxx.h>

#include <bit>
#include <climits>
#include <cstdint>

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

/// The common unit exponent s of one predicate call.
class ScaleFinder {
 public:
  /// A coordinate: s ≤ its lowest set bit.
  void add_coordinate(double x) {
    const DyadicParts p = split_double(x);
    if (p.mantissa != 0 && p.exponent < unit_) unit_ = p.exponent;
  }
  /// A weight (an area): 2s ≤ its lowest set bit.
  void add_weight(double w) {
    const DyadicParts p = split_double(w);
    if (p.mantissa == 0) return;
    const int half = p.exponent >= 0 ? p.exponent / 2 : -((-p.exponent + 1) / 2);
    if (half < unit_) unit_ = half;
  }
  /// s (0 if every input was zero).
  int unit() const { return unit_ == INT_MAX ? 0 : unit_; }

 private:
  int unit_ = INT_MAX;
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

/// Sign of an mpz as an int.
inline int sign_int(const mpz_class& v) { return mpz_sgn(v.get_mpz_t()); }

}  // namespace rstruct::predicates::detail
