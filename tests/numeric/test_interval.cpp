// Interval: every operation encloses the exact result (checked in GMP rationals) on
// random operands of all magnitudes, including subnormals, overflow and zero.
#include <rapidcheck/catch.h>

#include <catch2/catch.hpp>
#include <gmpxx.h>

#include <limits>
#include <random>

#include "rstruct/numeric/interval.hpp"
#include "support/degenerate.hpp"

using rstruct::Sign;
using rstruct::numeric::Interval;
using rstruct::numeric::next_down;
using rstruct::numeric::next_up;

namespace {

double random_double(std::mt19937_64& rng) {
  switch (rng() % 5) {
    case 0: return rstruct::testing::random_subnormal(rng);
    case 1: return rstruct::testing::random_magnitude(rng, -1074, 1023);
    case 2: return double(static_cast<int>(rng() % 7) - 3);
    default: return rstruct::testing::random_magnitude(rng, -60, 60);
  }
}

/// An interval around a random value, and a random exact point inside it.
std::pair<Interval, double> random_interval(std::mt19937_64& rng) {
  const double a = random_double(rng), b = random_double(rng);
  const double lo = std::fmin(a, b), hi = std::fmax(a, b);
  const double x = (rng() % 2 == 0) ? lo : hi;
  return {rng() % 3 == 0 ? Interval(x) : Interval(lo, hi), x};
}

bool encloses(const Interval& i, const mpq_class& exact) {
  if (std::isnan(i.lower()) || std::isnan(i.upper())) return true;  // undecided, never wrong
  const bool lo_ok = std::isinf(i.lower()) ? i.lower() < 0 : mpq_class(i.lower()) <= exact;
  const bool hi_ok = std::isinf(i.upper()) ? i.upper() > 0 : exact <= mpq_class(i.upper());
  return lo_ok && hi_ok;
}

}  // namespace

TEST_CASE("next_up and next_down step one ulp, through zero and subnormals") {
  CHECK(next_up(0.0) == std::numeric_limits<double>::denorm_min());
  CHECK(next_down(0.0) == -std::numeric_limits<double>::denorm_min());
  CHECK(next_up(1.0) == std::nextafter(1.0, 2.0));
  CHECK(next_down(1.0) == std::nextafter(1.0, 0.0));
  CHECK(next_up(-1.0) == std::nextafter(-1.0, 0.0));
  CHECK(next_up(-std::numeric_limits<double>::denorm_min()) == 0.0);
  CHECK(next_up(std::numeric_limits<double>::max()) == HUGE_VAL);
  CHECK(next_up(HUGE_VAL) == HUGE_VAL);
  CHECK(next_down(-HUGE_VAL) == -HUGE_VAL);
}

TEST_CASE("interval operations enclose the exact result") {
  const std::uint64_t seed = 0x1a7e0001;
  INFO("seed " << seed);
  std::mt19937_64 rng(seed);
  for (int n = 0; n < 20000; ++n) {
    const auto [a, x] = random_interval(rng);
    const auto [b, y] = random_interval(rng);
    const mpq_class qx(x), qy(y);
    REQUIRE(encloses(a + b, qx + qy));
    REQUIRE(encloses(a - b, qx - qy));
    REQUIRE(encloses(a * b, qx * qy));
    REQUIRE(encloses(-a, -qx));
  }
}

TEST_CASE("interval sign decides only when every point has that sign") {
  CHECK(Interval(1, 2).sign() == Sign::positive);
  CHECK(Interval(-2, -1).sign() == Sign::negative);
  CHECK(Interval(0).sign() == Sign::zero);
  CHECK_FALSE(Interval(-1, 1).sign().has_value());
  CHECK_FALSE(Interval(0, 1).sign().has_value());
  const double nan = std::nan("");
  CHECK_FALSE(Interval(nan, nan).sign().has_value());
  CHECK_FALSE((Interval(HUGE_VAL) - Interval(HUGE_VAL)).sign().has_value());
  CHECK_FALSE((Interval(0) * Interval(HUGE_VAL)).sign().has_value());
  // 0.1 + 0.2 − 0.3 is not zero in doubles, but the interval cannot claim a sign for the
  // real 1/10 + 2/10 − 3/10 of the rounded inputs without deciding: it must enclose it.
  const Interval s = Interval(0.1) + Interval(0.2) - Interval(0.3);
  CHECK(encloses(s, mpq_class(0.1) + mpq_class(0.2) - mpq_class(0.3)));
}
