#include "rstruct/numeric/dyadic.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <string>

#include "rstruct/core/error.hpp"

namespace rstruct::numeric {

Dyadic::Dyadic(double x) {
  if (!std::isfinite(x)) {
    throw InvalidInput("numeric::Dyadic: non-finite value " + std::to_string(x));
  }
  const auto bits = std::bit_cast<std::uint64_t>(x);
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  std::uint64_t m = bits & ((std::uint64_t{1} << 52) - 1);
  e_ = -1074;
  if (biased != 0) {
    m |= std::uint64_t{1} << 52;
    e_ = biased - 1075;
  }
  m_ = static_cast<unsigned long>(m);
  if ((bits >> 63) != 0) m_ = -m_;
}

Dyadic operator+(const Dyadic& a, const Dyadic& b) {
  if (a.m_ == 0) return b;
  if (b.m_ == 0) return a;
  // Align on the smaller exponent: the other mantissa is shifted left, exactly.
  const Dyadic& low = a.e_ <= b.e_ ? a : b;
  const Dyadic& high = a.e_ <= b.e_ ? b : a;
  mpz_class shifted;
  mpz_mul_2exp(shifted.get_mpz_t(), high.m_.get_mpz_t(),
               static_cast<mp_bitcnt_t>(high.e_ - low.e_));
  return {low.m_ + shifted, low.e_};
}

mpq_class Dyadic::to_mpq() const {
  mpq_class q(m_);
  if (e_ >= 0) {
    mpq_mul_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(e_));
  } else {
    mpq_div_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(-e_));
  }
  return q;
}

}  // namespace rstruct::numeric
