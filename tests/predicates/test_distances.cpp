// Distance and power comparisons against the rational oracle, with antisymmetry.
#include <rapidcheck/catch.h>

#include <catch2/catch.hpp>
#include <random>

#include "predicates/cases.hpp"
#include "predicates/rational_oracle.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/predicates/predicates.hpp"

using namespace rstruct;
using namespace rstruct::testing;
namespace pr = rstruct::predicates;

TEST_CASE("distance and power comparisons agree with the rational oracle") {
  const std::uint64_t seed = 0x5eed0007;
  INFO("seed " << seed);
  std::mt19937_64 rng(seed);
  for (int f = 0; f < static_cast<int>(Family::count_); ++f) {
    const auto fam = static_cast<Family>(f);
    INFO("family " << family_name(fam));
    for (int n = 0; n < 1500; ++n) {
      const auto p = make_weighted<3>(rng, fam);
      const Point3& x = p[0].c;
      const int dist = oracle::compare_power_distance(x, {p[1].c, 0}, {p[2].c, 0});
      REQUIRE(to_int(pr::compare_squared_distance(x, p[1].c, p[2].c)) == dist);
      REQUIRE(to_int(pr::compare_squared_distance(x, p[2].c, p[1].c)) == -dist);
      const int pow = oracle::compare_power_distance(x, p[1], p[2]);
      REQUIRE(to_int(pr::compare_power_distance(x, p[1], p[2])) == pow);
      REQUIRE(to_int(pr::compare_power_distance(x, p[2], p[1])) == -pow);
      const int ps = oracle::compare_power_distance(x, p[1], {x, 0});
      REQUIRE(to_int(pr::power_sign(x, p[1])) == ps);
      const double r = std::sqrt(std::fabs(p[2].w));
      REQUIRE(to_int(pr::side_of_ball(x, p[1].c, r)) == oracle::side_of_ball(x, p[1].c, r));
      // A point on the sphere exactly: integer Pythagorean data.
      REQUIRE(pr::side_of_ball({3, 4, 12}, {0, 0, 0}, 13) == Sign::zero);
    }
  }
}

TEST_CASE("comparisons reject non-finite input") {
  CHECK_THROWS_AS(pr::side_of_ball({0, 0, 0}, {1, 1, 1}, HUGE_VAL), InvalidInput);
  CHECK_THROWS_AS(pr::power_sign({0, 0, 0}, {{1, 1, 1}, std::nan("")}), InvalidInput);
  CHECK_THROWS_AS(pr::compare_squared_distance({0, 0, -HUGE_VAL}, {1, 1, 1}, {0, 0, 0}),
                  InvalidInput);
}
