#pragma once
/// \file
/// Dyadic: an exact dyadic rational m·2^e (GMP integer m, integer e), the exact stage of
/// numeric::filtered_sign. Every finite double converts exactly; sums, differences and
/// products stay exact without any gcd (cheaper than mpq_class). Only +, − and × are
/// provided: write predicates as polynomials in the input doubles.

#include <gmpxx.h>

#include "rstruct/predicates/sign.hpp"

namespace rstruct::numeric {

class Dyadic {
 public:
  Dyadic() = default;
  /// Exactly x. \throws rstruct::InvalidInput if x is NaN or infinite.
  Dyadic(double x);  // NOLINT(google-explicit-constructor): numeric type
  /// m · 2^e.
  Dyadic(mpz_class m, long e) : m_(std::move(m)), e_(e) {}

  Sign sign() const { return static_cast<Sign>(mpz_sgn(m_.get_mpz_t())); }
  const mpz_class& mantissa() const { return m_; }
  long exponent() const { return e_; }
  /// The exact value as a GMP rational (for tests and output).
  mpq_class to_mpq() const;

  friend Dyadic operator-(const Dyadic& a) { return {-a.m_, a.e_}; }
  friend Dyadic operator+(const Dyadic& a, const Dyadic& b);
  friend Dyadic operator-(const Dyadic& a, const Dyadic& b) { return a + (-b); }
  friend Dyadic operator*(const Dyadic& a, const Dyadic& b) { return {a.m_ * b.m_, a.e_ + b.e_}; }
  Dyadic& operator+=(const Dyadic& b) { return *this = *this + b; }
  Dyadic& operator-=(const Dyadic& b) { return *this = *this - b; }
  Dyadic& operator*=(const Dyadic& b) { return *this = *this * b; }

 private:
  mpz_class m_ = 0;
  long e_ = 0;
};

}  // namespace rstruct::numeric
