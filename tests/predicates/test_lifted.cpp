// insphere and power_test (unperturbed) against the rational oracle (circumcentre /
// orthocentre and powers), and metamorphic properties.
#include <rapidcheck/catch.h>

#include <catch2/catch.hpp>
#include <cstdio>
#include <random>

#include "predicates/cases.hpp"
#include "predicates/rational_oracle.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/predicates/predicates.hpp"

using namespace rstruct;
using namespace rstruct::testing;
namespace pr = rstruct::predicates;

namespace {
void print_case(const char* what, const std::array<WeightedPoint, 5>& p) {
  std::printf("%s mismatch:", what);
  for (const auto& q : p) std::printf(" (%a %a %a; %a)", q.c.x, q.c.y, q.c.z, q.w);
  std::printf("\n");
}
}  // namespace

TEST_CASE("insphere convention: the centre is inside, a far point outside") {
  const Point3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0}, d{0, 0, 1};
  REQUIRE(pr::orient3d(a, b, c, d) == Sign::positive);
  CHECK(pr::insphere(a, b, c, d, {0.5, 0.5, 0.5}) == Sign::positive);
  CHECK(pr::insphere(a, b, c, d, {5, 5, 5}) == Sign::negative);
  CHECK(pr::insphere(a, b, c, d, {1, 1, 0}) == Sign::zero);
  CHECK(pr::insphere(b, a, c, d, {0.5, 0.5, 0.5}) == Sign::negative);  // flips with orientation
  // Weights: a heavy query point is in conflict even far away.
  CHECK(pr::power_test({a, 0}, {b, 0}, {c, 0}, {d, 0}, {{5, 5, 5}, 100}) == Sign::positive);
  CHECK(pr::power_test({a, 0}, {b, 0}, {c, 0}, {d, 0}, {{5, 5, 5}, 0}) == Sign::negative);
}

TEST_CASE("insphere agrees with the rational oracle on every input family") {
  const std::uint64_t seed = 0x5eed0002;
  INFO("seed " << seed);
  std::mt19937_64 rng(seed);
  for (int f = 0; f < static_cast<int>(Family::count_); ++f) {
    const auto fam = static_cast<Family>(f);
    INFO("family " << family_name(fam));
    for (int n = 0; n < 1000; ++n) {
      const auto p = make_points<5>(rng, fam);
      const int expected = oracle::insphere(p[0], p[1], p[2], p[3], p[4]);
      const int got = to_int(pr::insphere(p[0], p[1], p[2], p[3], p[4]));
      if (pr::orient3d(p[0], p[1], p[2], p[3]) == Sign::zero) continue;  // oracle undefined
      if (got != expected) print_case("insphere", {{{p[0]}, {p[1]}, {p[2]}, {p[3]}, {p[4]}}});
      REQUIRE(got == expected);
    }
  }
}

TEST_CASE("power_test agrees with the rational oracle on every input family") {
  const std::uint64_t seed = 0x5eed0003;
  INFO("seed " << seed);
  std::mt19937_64 rng(seed);
  for (int f = 0; f < static_cast<int>(Family::count_); ++f) {
    const auto fam = static_cast<Family>(f);
    INFO("family " << family_name(fam));
    int zeros = 0;
    for (int n = 0; n < 1000; ++n) {
      const auto p = make_weighted<5>(rng, fam);
      if (pr::orient3d(p[0].c, p[1].c, p[2].c, p[3].c) == Sign::zero) continue;
      const int expected = oracle::power_test(p[0], p[1], p[2], p[3], p[4]);
      const int got = to_int(pr::power_test(p[0], p[1], p[2], p[3], p[4]));
      if (got != expected) print_case("power_test", p);
      REQUIRE(got == expected);
      zeros += expected == 0;
    }
    INFO("zeros " << zeros);
    if (fam == Family::grid) CHECK(zeros > 0);
  }
}

TEST_CASE("zero weights reduce the power test to insphere; flat cells give zero") {
  rc::prop("zero weights", [](std::uint64_t seed, unsigned family) {
    std::mt19937_64 rng(seed);
    const auto p = make_points<5>(rng, static_cast<Family>(family % int(Family::count_)));
    RC_ASSERT(pr::power_test({p[0], 0}, {p[1], 0}, {p[2], 0}, {p[3], 0}, {p[4], 0}) ==
              pr::insphere(p[0], p[1], p[2], p[3], p[4]));
  });
  // Equal weights everywhere also reduce to insphere (the lifted heights shift equally).
  rc::prop("equal weights", [](std::uint64_t seed, unsigned family) {
    std::mt19937_64 rng(seed);
    const auto p = make_points<5>(rng, static_cast<Family>(family % 4));  // small, exact
    const double w = 0.5;
    RC_ASSERT(pr::power_test({p[0], w}, {p[1], w}, {p[2], w}, {p[3], w}, {p[4], w}) ==
              pr::insphere(p[0], p[1], p[2], p[3], p[4]));
  });
}

TEST_CASE("power_test flips under odd permutations of the cell, even ones keep it") {
  rc::prop("permutations", [](std::uint64_t seed, unsigned family) {
    std::mt19937_64 rng(seed);
    const auto p = make_weighted<5>(rng, static_cast<Family>(family % int(Family::count_)));
    const Sign s = pr::power_test(p[0], p[1], p[2], p[3], p[4]);
    RC_ASSERT(pr::power_test(p[1], p[0], p[2], p[3], p[4]) == -s);
    RC_ASSERT(pr::power_test(p[0], p[1], p[3], p[2], p[4]) == -s);
    RC_ASSERT(pr::power_test(p[1], p[2], p[0], p[3], p[4]) == s);
    RC_ASSERT(pr::power_test(p[3], p[2], p[1], p[0], p[4]) == s);
    // Moving the query into the cell: an odd permutation of all five rows of the 5×5
    // determinant flips the sign (a transposition of e and d).
    RC_ASSERT(pr::power_test(p[0], p[1], p[2], p[4], p[3]) == -s);
  });
}

TEST_CASE("power_test is invariant under exact translations and power-of-two scalings") {
  rc::prop("translation and scaling", [](std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<std::int64_t> k(-(std::int64_t{1} << 20), std::int64_t{1} << 20);
    auto coord = [&] { return std::ldexp(static_cast<double>(k(rng)), -10); };
    std::array<WeightedPoint, 5> p;
    for (auto& q : p) q = {{coord(), coord(), coord()}, std::ldexp(double(k(rng)), -20)};
    if (seed % 2 == 0) {  // make it degenerate: weights orthogonal to a sphere
      const Point3 z{coord(), coord(), coord()};
      for (auto& q : p) q.w = squared_distance(q.c, z) - 1.0;  // exact: < 2^53 units
    }
    const Vec3 t{coord(), coord(), coord()};
    const Sign s = pr::power_test(p[0], p[1], p[2], p[3], p[4]);
    auto moved = p;
    for (auto& q : moved) q.c += t;  // weights unchanged: translation
    RC_ASSERT(pr::power_test(moved[0], moved[1], moved[2], moved[3], moved[4]) == s);
    const int e = *rc::gen::inRange(-200, 200);
    auto scaled = p;
    for (auto& q : scaled) q = {scale_pow2(q.c, e), std::ldexp(q.w, 2 * e)};
    RC_ASSERT(pr::power_test(scaled[0], scaled[1], scaled[2], scaled[3], scaled[4]) == s);
  });
}

TEST_CASE("power_test rejects non-finite weights") {
  const WeightedPoint a{{0, 0, 0}, 0}, b{{1, 0, 0}, 0}, c{{0, 1, 0}, 0}, d{{0, 0, 1}, 0};
  CHECK_THROWS_AS(pr::power_test(a, b, c, d, {{0.5, 0.5, 0.5}, std::nan("")}), InvalidInput);
  CHECK_THROWS_AS(pr::power_test(a, b, c, {{0, 0, 1}, HUGE_VAL}, {{0.2, 0.2, 0.2}, 0}),
                  InvalidInput);
}
