// filtered_sign: equals the exact sign (GMP rationals) of the same polynomial, decides
// in the interval stage on easy inputs and in the exact stage on degenerate ones.
#include <rapidcheck/catch.h>

#include <catch2/catch.hpp>
#include <gmpxx.h>

#include <random>

#include "rstruct/numeric/filtered_sign.hpp"
#include "support/degenerate.hpp"

using rstruct::Sign;
using namespace rstruct::numeric;

namespace {

// Orientation of three 2D points and the in-circle determinant, as generic lambdas.
const auto orient2d = [](auto ax, auto ay, auto bx, auto by, auto cx, auto cy) {
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
};
const auto incircle = [](auto ax, auto ay, auto bx, auto by, auto cx, auto cy, auto dx, auto dy) {
  const auto adx = ax - dx, ady = ay - dy, bdx = bx - dx, bdy = by - dy, cdx = cx - dx,
             cdy = cy - dy;
  const auto al = adx * adx + ady * ady, bl = bdx * bdx + bdy * bdy, cl = cdx * cdx + cdy * cdy;
  return al * (bdx * cdy - bdy * cdx) - bl * (adx * cdy - ady * cdx) + cl * (adx * bdy - ady * bdx);
};

/// mpq_class behind concrete operators: gmpxx's expression templates would dangle
/// inside the lambdas' `auto` locals.
struct Q {
  mpq_class v;
  friend Q operator+(const Q& a, const Q& b) { return {a.v + b.v}; }
  friend Q operator-(const Q& a, const Q& b) { return {a.v - b.v}; }
  friend Q operator*(const Q& a, const Q& b) { return {a.v * b.v}; }
};

}  // namespace

TEST_CASE("filtered_sign equals the exact sign of the polynomial") {
  const std::uint64_t seed = 0xf1175001;
  INFO("seed " << seed);
  std::mt19937_64 rng(seed);
  FilteredSignStats stats;
  for (int n = 0; n < 3000; ++n) {
    double v[8];
    const int family = n % 4;
    for (double& x : v) {
      if (family == 0) x = std::uniform_real_distribution<double>(-1, 1)(rng);
      if (family == 1) x = double(static_cast<int>(rng() % 5));  // grid: many zeros
      if (family == 2) x = rstruct::testing::random_magnitude(rng, -600, 600);
      if (family == 3) x = rstruct::testing::perturb_ulps(double(static_cast<int>(rng() % 5)), static_cast<std::int64_t>(rng() % 3));
    }
    Q q[8];
    for (int i = 0; i < 8; ++i) q[i].v = v[i];
    const Sign o = filtered_sign(&stats, orient2d, v[0], v[1], v[2], v[3], v[4], v[5]);
    REQUIRE(static_cast<int>(o) == sgn(orient2d(q[0], q[1], q[2], q[3], q[4], q[5]).v));
    const Sign c = filtered_sign(&stats, incircle, v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]);
    REQUIRE(static_cast<int>(c) ==
            sgn(incircle(q[0], q[1], q[2], q[3], q[4], q[5], q[6], q[7]).v));
  }
  CHECK(stats.interval > 1000);  // random inputs mostly decided by intervals
  CHECK(stats.exact > 500);      // grid inputs need the exact stage
}
