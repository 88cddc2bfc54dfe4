// Dyadic: exact conversion of every double, exact ring operations (checked in GMP
// rationals).
#include <rapidcheck/catch.h>

#include <catch2/catch.hpp>
#include <gmpxx.h>

#include <random>

#include "rstruct/core/error.hpp"
#include "rstruct/numeric/dyadic.hpp"
#include "support/degenerate.hpp"

using rstruct::numeric::Dyadic;

TEST_CASE("Dyadic converts doubles exactly and computes exactly") {
  const std::uint64_t seed = 0xd1ad0001;
  INFO("seed " << seed);
  std::mt19937_64 rng(seed);
  auto draw = [&] {
    switch (rng() % 4) {
      case 0: return rstruct::testing::random_subnormal(rng);
      case 1: return rstruct::testing::random_magnitude(rng, -1074, 1023);
      case 2: return 0.0;
      default: return rstruct::testing::random_magnitude(rng, -30, 30);
    }
  };
  for (int n = 0; n < 5000; ++n) {
    const double x = draw(), y = draw(), z = draw();
    const mpq_class qx(x), qy(y), qz(z);
    const Dyadic dx(x), dy(y), dz(z);
    REQUIRE(dx.to_mpq() == qx);
    REQUIRE((dx + dy).to_mpq() == qx + qy);
    REQUIRE((dx - dy).to_mpq() == qx - qy);
    REQUIRE((dx * dy - dz).to_mpq() == qx * qy - qz);
    REQUIRE(static_cast<int>((dx * dy - dz).sign()) == sgn(mpq_class(qx * qy - qz)));
  }
  CHECK_THROWS_AS(Dyadic(HUGE_VAL), rstruct::InvalidInput);
  CHECK_THROWS_AS(Dyadic(std::nan("")), rstruct::InvalidInput);
}
