// The dynamic filter of the lifted determinant (in-sphere and power tests): it agrees with
// the rational oracle wherever it decides, on every input family and on the near-
// cospherical long, thin cells that defeat the semi-static filter, where it must decide a
// good share of them; its guard keeps it silent on huge, tiny and non-finite inputs.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

#include "predicates/cases.hpp"
#include "predicates/rational_oracle.hpp"
#include "rstruct/predicates/detail/dynamic_filter.hpp"
#include "rstruct/predicates/predicates.hpp"

using namespace rstruct;
using namespace rstruct::testing;
namespace pr = rstruct::predicates;
namespace pd = rstruct::predicates::detail;

namespace {

int dynamic(const std::array<WeightedPoint, 5>& p, bool weighted) {
  if (!weighted) {
    return pd::lifted4_dynamic_filter<false>(p[0].c, p[1].c, p[2].c, p[3].c, p[4].c, 0, 0, 0,
                                             0, 0);
  }
  return pd::lifted4_dynamic_filter<true>(p[0].c, p[1].c, p[2].c, p[3].c, p[4].c, p[0].w,
                                          p[1].w, p[2].w, p[3].w, p[4].w);
}

int semi_static(const std::array<WeightedPoint, 5>& p, bool weighted) {
  if (!weighted) return pd::insphere_filter(p[0].c, p[1].c, p[2].c, p[3].c, p[4].c);
  return pd::lifted4_filter<true>(p[0], p[1], p[2], p[3], p[4]);
}

int oracle_sign(const std::array<WeightedPoint, 5>& p) {
  return oracle::power_test(p[0], p[1], p[2], p[3], p[4]);
}

bool flat(const std::array<WeightedPoint, 5>& p) {
  return oracle::orient3d(p[0].c, p[1].c, p[2].c, p[3].c) == 0;
}

/// The dynamic filter's answer, required to be the oracle's sign when it decides.
int checked_dynamic(const std::array<WeightedPoint, 5>& p, bool weighted) {
  const int d = dynamic(p, weighted);
  if (d != pd::kUndecided) REQUIRE(d == oracle_sign(p));
  return d;
}

/// Five points on (or, weighted, orthogonal to) a sphere of radius 1 about a centre at
/// distance 3 from the origin (as the balls inscribed in a torus's tube), rounded to
/// doubles: three in a small cap, two spread around, so the cell is long and thin; the
/// fifth point is then moved off the sphere by a relative 10^-11 to 10^-9, so that it is
/// nearly, but not within rounding, on the cell's circumsphere (orthosphere): there the
/// semi-static filter mostly fails and the dynamic one mostly decides.
template <class Rng>
std::array<WeightedPoint, 5> thin_cospherical(Rng& rng, bool weighted, bool offset = true) {
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> cap(-0.03, 0.03), radius(0.6, 1.6), exponent(-11, -9);
  const double phi = std::uniform_real_distribution<double>(0, 6.283185307179586)(rng);
  const Vec3 centre{3 * std::cos(phi), 3 * std::sin(phi), 0.1 * normal(rng)};
  const Vec3 axis = normalized(Vec3{normal(rng), normal(rng), normal(rng)});
  std::array<WeightedPoint, 5> p;
  for (std::size_t i = 0; i < 5; ++i) {
    const Vec3 v = i < 3 ? normalized(axis + Vec3{cap(rng), cap(rng), cap(rng)})
                         : normalized(Vec3{normal(rng), normal(rng), normal(rng)});
    const double r = weighted ? radius(rng) : 1.0;
    p[i].c = centre + v * r;
    // Power of the point against the unit sphere: orthogonal up to rounding.
    p[i].w = weighted ? squared_distance(p[i].c, centre) - 1.0 : 0.0;
  }
  const double off = offset ? std::pow(10.0, exponent(rng)) * (rng() % 2 == 0 ? 1 : -1) : 0.0;
  if (weighted) {
    p[4].w += off;
  } else {
    p[4].c = centre + (p[4].c - centre) * (1 + off);
  }
  return p;
}

}  // namespace

TEST_CASE("dynamic filter agrees with the oracle on every input family") {
  const std::uint64_t seed = 0x5eed0701;
  INFO("seed " << seed);
  std::mt19937_64 rng(seed);
  for (const bool weighted : {false, true}) {
    for (int f = 0; f < static_cast<int>(Family::count_); ++f) {
      const Family family = static_cast<Family>(f);
      if (family == Family::coplanar || family == Family::collinear) continue;  // flat cells
      INFO("family " << family_name(family) << (weighted ? ", weighted" : ""));
      long tested = 0;
      for (int n = 0; n < 600; ++n) {
        std::array<WeightedPoint, 5> p;
        if (weighted) {
          p = make_weighted<5>(rng, family);
        } else {
          const auto q = make_points<5>(rng, family);
          for (std::size_t i = 0; i < 5; ++i) p[i] = {q[i], 0};
        }
        if (flat(p)) continue;
        ++tested;
        checked_dynamic(p, weighted);
      }
      CHECK(tested > 0);
    }
  }
}

TEST_CASE("dynamic filter decides the thin, nearly cospherical cells the semi-static one cannot") {
  const std::uint64_t seed = 0x5eed0702;
  INFO("seed " << seed);
  std::mt19937_64 rng(seed);
  for (const bool weighted : {false, true}) {
    INFO((weighted ? "power test" : "in-sphere test"));
    long hard = 0, decided = 0;
    for (int n = 0; n < 4000; ++n) {
      const auto p = thin_cospherical(rng, weighted);
      if (flat(p)) continue;
      const int d = checked_dynamic(p, weighted);
      if (semi_static(p, weighted) != pd::kUndecided || oracle_sign(p) == 0) continue;
      ++hard;
      decided += d != pd::kUndecided;
    }
    INFO(decided << " of " << hard << " cases the semi-static filter left undecided");
    // The family must be hard for the semi-static filter, and the dynamic one must take a
    // good share of it: about half here (seeds vary by a few percent), and 89 % of the
    // conflict tests that reached the exact stage on 10^6 points on a torus.
    CHECK(hard > 1000);
    CHECK(decided * 3 > hard);
  }
}

// Cospherical up to the rounding of the input: the computed value is mostly rounding
// error, the hardest case for the bound. With a constant of u/4 instead of 18u the filter
// decides some of these wrongly and this test fails (with u it passes: the worst case is
// rare; the constant itself is checked by proofs/filter_bounds.cpp).
TEST_CASE("dynamic filter on points cospherical up to rounding: never wrong") {
  const std::uint64_t seed = 0x5eed0703;
  INFO("seed " << seed);
  std::mt19937_64 rng(seed);
  for (const bool weighted : {false, true}) {
    INFO((weighted ? "power test" : "in-sphere test"));
    long decided = 0, tested = 0;
    for (int n = 0; n < 6000; ++n) {
      const auto p = thin_cospherical(rng, weighted, false);
      if (flat(p)) continue;
      ++tested;
      decided += checked_dynamic(p, weighted) != pd::kUndecided;
    }
    INFO(decided << " of " << tested << " decided");
    CHECK(tested > 5000);
  }
}

TEST_CASE("dynamic filter: the guard keeps it silent outside its range") {
  const Point3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0}, d{0, 0, 1}, e{0.25, 0.25, 0.25};
  // A plain case decides (positive: e inside the circumsphere of the positive cell).
  REQUIRE(pd::lifted4_dynamic_filter<false>(a, b, c, d, e, 0, 0, 0, 0, 0) == 1);
  // Differences above 2^100, a bound below 2^-700: left to the exact stage.
  const auto at_scale = [&](int k) {
    return pd::lifted4_dynamic_filter<false>(scale_pow2(a, k), scale_pow2(b, k), scale_pow2(c, k),
                                             scale_pow2(d, k), scale_pow2(e, k), 0, 0, 0, 0, 0);
  };
  CHECK(at_scale(101) == pd::kUndecided);
  CHECK(at_scale(99) == 1);
  CHECK(at_scale(-150) == pd::kUndecided);
  CHECK(at_scale(-100) == 1);
  // Weight differences above 2^200.
  CHECK(pd::lifted4_dynamic_filter<true>(a, b, c, d, e, 0, 0, 0, 0, 0x1p201) == pd::kUndecided);
  CHECK(pd::lifted4_dynamic_filter<true>(a, b, c, d, e, 0, 0, 0, 0, -0.01) == 1);
  // Non-finite input.
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK(pd::lifted4_dynamic_filter<false>(a, b, c, d, {inf, 0, 0}, 0, 0, 0, 0, 0) ==
        pd::kUndecided);
  CHECK(pd::lifted4_dynamic_filter<false>({nan, 0, 0}, b, c, d, e, 0, 0, 0, 0, 0) ==
        pd::kUndecided);
  CHECK(pd::lifted4_dynamic_filter<true>(a, b, c, d, e, nan, 0, 0, 0, 0) == pd::kUndecided);
  // An exact zero (e on the circumsphere) is never decided.
  CHECK(pd::lifted4_dynamic_filter<false>(a, b, c, d, {1, 1, 0}, 0, 0, 0, 0, 0) ==
        pd::kUndecided);
}
