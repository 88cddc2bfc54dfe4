// BoundedInt against GMP on random expression trees of all sizes that fit, and its
// overflow check.
#include <rapidcheck/catch.h>

#include <catch2/catch.hpp>
#include <gmpxx.h>

#include <random>

#include "rstruct/core/error.hpp"
#include "rstruct/numeric/bounded_int.hpp"

using rstruct::numeric::BoundedInt;
using Int = BoundedInt<6>;

namespace {

mpz_class to_mpz(const Int& v) {
  mpz_class r = 0;
  for (int i = v.limbs() - 1; i >= 0; --i) {
    r <<= 64;
    r += mpz_class(static_cast<unsigned long>(v.limb(i)));
  }
  return v.is_negative() ? mpz_class(-r) : r;
}

std::pair<Int, mpz_class> random_leaf(std::mt19937_64& rng) {
  const std::uint64_t m = rng() >> (rng() % 64);
  const int shift = static_cast<int>(rng() % 70);
  const bool neg = rng() % 2 == 0;
  mpz_class z(static_cast<unsigned long>(m));
  z <<= static_cast<unsigned>(shift);
  if (neg) z = -z;
  return {Int::shifted(m, shift, neg), z};
}

}  // namespace

TEST_CASE("BoundedInt matches GMP on random sums, differences and products") {
  const std::uint64_t seed = 0xb0dd0001;
  INFO("seed " << seed);
  std::mt19937_64 rng(seed);
  for (int n = 0; n < 20000; ++n) {
    auto [a, za] = random_leaf(rng);
    auto [b, zb] = random_leaf(rng);
    REQUIRE(to_mpz(a) == za);
    REQUIRE(to_mpz(a + b) == za + zb);
    REQUIRE(to_mpz(a - b) == za - zb);
    REQUIRE(to_mpz(b - a) == zb - za);
    REQUIRE(to_mpz(a - a) == 0);
    REQUIRE((a - a).sign() == 0);
    REQUIRE(to_mpz(-a) == -za);
    const Int p = a * b;  // at most 2·(64 + 70) = 268 bits: fits in 6 limbs
    REQUIRE(to_mpz(p) == za * zb);
    REQUIRE(p.sign() == sgn(za * zb));
    auto [c, zc] = random_leaf(rng);
    REQUIRE(to_mpz(p + c) == za * zb + zc);
    REQUIRE(to_mpz(p - c * c) == za * zb - zc * zc);
  }
}

TEST_CASE("BoundedInt carries and borrows across every limb") {
  const Int max64 = Int::shifted(~std::uint64_t{0}, 0, false);
  const Int one = Int(1);
  const Int big = max64 + one;  // 2^64
  CHECK(big.limbs() == 2);
  CHECK(to_mpz(big) == mpz_class(1) << 64);
  CHECK(to_mpz(big - one) == (mpz_class(1) << 64) - 1);
  const Int p = big * big * big * big * big;  // 2^320
  CHECK(to_mpz(p - one) == (mpz_class(1) << 320) - 1);
  CHECK(to_mpz(one - p) == 1 - (mpz_class(1) << 320));
}

TEST_CASE("BoundedInt throws InternalError instead of overflowing") {
  const Int big = Int::shifted(1, 300, false);
  CHECK_THROWS_AS(big * big, rstruct::InternalError);
  CHECK_THROWS_AS(Int::shifted(1, 6 * 64, false), rstruct::InternalError);
  const Int top = Int::shifted(~std::uint64_t{0}, 5 * 64, false);
  CHECK_THROWS_AS(top + top, rstruct::InternalError);
}
