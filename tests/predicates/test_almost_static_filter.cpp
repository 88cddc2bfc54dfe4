// AlmostStaticFilter: the same signs as the rational oracle (and so as the free
// predicates) for inputs inside its box, on boxes from tiny to huge, with nearly
// degenerate inputs; boxes below the guard never decide by the static bound.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "predicates/cases.hpp"
#include "predicates/rational_oracle.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/predicates/almost_static_filter.hpp"

using namespace rstruct;
using namespace rstruct::testing;
namespace pr = rstruct::predicates;

namespace {

/// A point of the box [lo, lo + w]^3 on a grid of 2^-bits·w: the grids make exactly
/// degenerate configurations frequent at every scale.
template <class Rng>
Point3 grid_point(Rng& rng, double lo, double w, int bits) {
  std::uniform_int_distribution<std::int64_t> k(0, std::int64_t{1} << bits);
  const auto c = [&] { return lo + std::ldexp(w, -bits) * static_cast<double>(k(rng)); };
  return {c(), c(), c()};
}

}  // namespace

TEST_CASE("AlmostStaticFilter agrees with the oracle on boxes of every scale") {
  const std::uint64_t seed = 0x5eed0201;
  INFO("seed " << seed);
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> scale(-400, 400);
  long non_degenerate = 0, total = 0;
  for (int box_n = 0; box_n < 60; ++box_n) {
    const int e = box_n == 0 ? -1060 : scale(rng);  // box 0: extents below every guard
    const double w = std::ldexp(1.0, e), lo = -std::ldexp(1.5, e);
    const pr::AlmostStaticFilter filter({lo, lo, lo}, {lo + w, lo + w, lo + w});
    if (box_n == 0) {
      CHECK(filter.orient3d_bound() == HUGE_VAL);
      CHECK(filter.insphere_bound() == HUGE_VAL);
    }
    INFO("box exponent " << e);
    for (int n = 0; n < 200; ++n) {
      const int bits = n % 3 == 0 ? 2 : 30;
      std::array<Point3, 5> p;
      for (auto& q : p) q = grid_point(rng, lo, w, bits);
      if (n % 5 == 1) p[3] = p[0];  // coincident
      const int o = oracle::orient3d(p[0], p[1], p[2], p[3]);
      REQUIRE(to_int(filter.orient3d(p[0], p[1], p[2], p[3])) == o);
      if (o == 0) continue;  // the oracle's insphere needs a non-flat cell
      REQUIRE(to_int(filter.insphere(p[0], p[1], p[2], p[3], p[4])) ==
              oracle::insphere(p[0], p[1], p[2], p[3], p[4]));
      ++total;
      non_degenerate += o != 0;
    }
  }
  CHECK(non_degenerate > total / 2);
}

TEST_CASE("AlmostStaticFilter on the unit box: nearly cospherical integer points") {
  const pr::AlmostStaticFilter filter({-1, -1, -1}, {1, 1, 1});
  const std::uint64_t seed = 0x5eed0202;
  INFO("seed " << seed);
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::size_t> pick(0, sphere_65().size() - 1);
  for (int n = 0; n < 3000; ++n) {
    std::array<Point3, 5> p;
    for (auto& q : p) q = sphere_65()[pick(rng)] * 0x1p-7;
    if (n % 2 == 0) p[n % 5] = perturb_point(rng, p[n % 5], std::int64_t{1} << (n % 40));
    const int o = oracle::orient3d(p[0], p[1], p[2], p[3]);
    REQUIRE(to_int(filter.orient3d(p[0], p[1], p[2], p[3])) == o);
    if (o == 0) continue;
    REQUIRE(to_int(filter.insphere(p[0], p[1], p[2], p[3], p[4])) ==
            oracle::insphere(p[0], p[1], p[2], p[3], p[4]));
  }
}

TEST_CASE("AlmostStaticFilter on rounded nearly degenerate inputs (inexact evaluation)") {
  const pr::AlmostStaticFilter filter({-4, -4, -4}, {4, 4, 4});
  const std::uint64_t seed = 0x5eed0203;
  INFO("seed " << seed);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1), f(0.05, 0.3);
  std::uniform_int_distribution<std::size_t> pick(0, sphere_65().size() - 1);
  for (int n = 0; n < 20000; ++n) {
    // d = a + s(b − a) + t(c − a) rounded: coplanar up to rounding.
    const Point3 a{u(rng), u(rng), u(rng)}, b{u(rng), u(rng), u(rng)}, c{u(rng), u(rng), u(rng)};
    const double s = u(rng) * 0.5, t = u(rng) * 0.5;
    const Point3 d = a + (b - a) * s + (c - a) * t;
    REQUIRE(to_int(filter.orient3d(a, b, c, d)) == oracle::orient3d(a, b, c, d));
    // Integer points of a sphere times a non-dyadic factor: cospherical up to rounding.
    const double k = f(rng) / 65;
    std::array<Point3, 5> p;
    for (auto& q : p) q = sphere_65()[pick(rng)] * k;
    const int o = oracle::orient3d(p[0], p[1], p[2], p[3]);
    if (o == 0) continue;
    REQUIRE(to_int(filter.insphere(p[0], p[1], p[2], p[3], p[4])) ==
            oracle::insphere(p[0], p[1], p[2], p[3], p[4]));
  }
}

TEST_CASE("AlmostStaticFilter rejects empty or non-finite boxes and, checked, outside points") {
  CHECK_THROWS_AS(pr::AlmostStaticFilter({0, 0, 1}, {1, 1, 0}), InvalidInput);
  CHECK_THROWS_AS(pr::AlmostStaticFilter({0, 0, 0}, {1, HUGE_VAL, 1}), InvalidInput);
  const pr::AlmostStaticFilter filter({0, 0, 0}, {1, 1, 1});
  if (check_level() >= 2) {
    CHECK_THROWS_AS(filter.orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 2}), InvalidInput);
  }
  // A huge box: the bound overflows to +inf and every call goes to the full predicate.
  const pr::AlmostStaticFilter huge({-1e308, -1e308, -1e308}, {1e308, 1e308, 1e308});
  CHECK(huge.orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}) == Sign::positive);
}

TEST_CASE("AlmostStaticFilter two-stage filters: oracle signs, and small cells in a big box") {
  // Clusters of width 2^-k inside a box of width 2^10: the box bound cannot decide most of
  // their tests (their determinants are far below it); the second stage, the semi-static
  // bound on the same value, must decide them, and every decided sign must be the
  // oracle's. Weighted points use a weight range; some clusters are degenerate (grids).
  const std::uint64_t seed = 0x5eed0204;
  INFO("seed " << seed);
  std::mt19937_64 rng(seed);
  pr::AlmostStaticFilter filter({-512, -512, -512}, {512, 512, 512});
  const double wmax = 1.0;
  filter.set_weight_range(0.0, wmax);
  CHECK(filter.power_test_bound() < HUGE_VAL);
  std::uniform_real_distribution<double> centre(-500, 500), unit(0, 1);
  long box_undecided = 0, second_decided = 0, orient_second = 0;
  for (int n = 0; n < 20000; ++n) {
    const int k = 2 + n % 12;
    const double w = std::ldexp(1.0, -k);
    const Point3 o{centre(rng), centre(rng), centre(rng)};
    std::array<Point3, 5> p;
    for (auto& q : p) {
      q = n % 4 == 0 ? o + grid_point(rng, 0, w, 2) : o + Point3{w * unit(rng), w * unit(rng), w * unit(rng)};
    }
    const int o3 = oracle::orient3d(p[0], p[1], p[2], p[3]);
    REQUIRE(to_int(filter.orient3d_two_stage(p[0], p[1], p[2], p[3])) == o3);
    const double bx = p[1].x - p[0].x, by = p[1].y - p[0].y, bz = p[1].z - p[0].z;
    const double cx = p[2].x - p[0].x, cy = p[2].y - p[0].y, cz = p[2].z - p[0].z;
    const double dx = p[3].x - p[0].x, dy = p[3].y - p[0].y, dz = p[3].z - p[0].z;
    if (o3 != 0 && std::fabs(pr::detail::det3(bx, by, bz, cx, cy, cz, dx, dy, dz)) <=
                       filter.orient3d_bound()) {
      ++orient_second;
    }
    if (o3 == 0) continue;
    const int f = filter.insphere_filter_two_stage(p[0], p[1], p[2], p[3], p[4]);
    const int box = filter.insphere_filter(p[0], p[1], p[2], p[3], p[4]);
    const int exact = oracle::insphere(p[0], p[1], p[2], p[3], p[4]);
    if (box != pr::detail::kUndecided) REQUIRE(box == exact);
    if (f != pr::detail::kUndecided) REQUIRE(f == exact);
    if (box == pr::detail::kUndecided) {
      ++box_undecided;
      second_decided += f != pr::detail::kUndecided;
    }
    // Weighted: weights in [0, wmax], some equal (then the weight column is zero).
    std::array<double, 5> wt;
    for (auto& x : wt) x = n % 3 == 0 ? 0.25 : wmax * unit(rng) * w * w;
    const int g = filter.power_test_filter_two_stage(p[0], p[1], p[2], p[3], p[4], wt[0], wt[1],
                                                     wt[2], wt[3], wt[4]);
    if (g != pr::detail::kUndecided) {
      REQUIRE(g == oracle::power_test({p[0], wt[0]}, {p[1], wt[1]}, {p[2], wt[2]},
                                      {p[3], wt[3]}, {p[4], wt[4]}));
    }
  }
  // The second stages are exercised, and decide most of what the box bound cannot.
  CHECK(box_undecided > 1000);
  CHECK(second_decided > box_undecided / 2);
  CHECK(orient_second > 100);
}

TEST_CASE("AlmostStaticFilter weight range: rejected when empty or not finite") {
  pr::AlmostStaticFilter filter({0, 0, 0}, {1, 1, 1});
  CHECK(filter.power_test_bound() == HUGE_VAL);
  CHECK_THROWS_AS(filter.set_weight_range(1, 0), InvalidInput);
  CHECK_THROWS_AS(filter.set_weight_range(0, HUGE_VAL), InvalidInput);
  CHECK_THROWS_AS(filter.set_weight_range(std::nan(""), 0), InvalidInput);
  filter.set_weight_range(-1, 1);
  CHECK(filter.power_test_bound() < HUGE_VAL);
  if (check_level() >= 2) {
    CHECK_THROWS_AS(filter.power_test_filter_two_stage({0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                                                       {0, 0, 1}, {0.2, 0.2, 0.2}, 0, 0, 0, 2, 0),
                    InvalidInput);
  }
}
