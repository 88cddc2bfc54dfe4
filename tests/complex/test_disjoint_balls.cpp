// balls_certainly_disjoint: every "disjoint" it answers is true in exact arithmetic
// (|a − b|² > (ra + rb)², checked as d² − wa − wb > 0 and (d² − wa − wb)² > 4 wa wb in
// rationals), on random balls of many magnitudes and on balls placed within a few ulps of
// tangency; it does answer for balls clearly apart; and it agrees with the orthosphere
// predicate it stands in for.

#include "rstruct/complex/disjoint_balls.hpp"

#include <gmpxx.h>
#include <rapidcheck/catch.h>

#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "rstruct/complex/orthosphere_predicates.hpp"

using namespace rstruct;
using namespace rstruct::complex;

namespace {

/// Exact: the balls of weights wa, wb ≥ 0 around a and b are disjoint (not touching).
bool exactly_disjoint(const Point3& a, double wa, const Point3& b, double wb) {
  mpq_class d2 = 0;
  for (int j = 0; j < 3; ++j) {
    const mpq_class d = mpq_class(a[j]) - mpq_class(b[j]);
    d2 += d * d;
  }
  const mpq_class gap = d2 - mpq_class(wa) - mpq_class(wb);
  return sgn(gap) > 0 && gap * gap > 4 * mpq_class(wa) * mpq_class(wb);
}

bool certified(const Point3& a, double wa, const Point3& b, double wb) {
  return balls_certainly_disjoint(a, radius_upper_bound(wa), b, radius_upper_bound(wb));
}

/// A double m · 2^e with m uniform in [-1, 1) (2^20 steps) and e in [lo, hi].
double scaled(int lo, int hi) {
  const double m = *rc::gen::inRange(-(1 << 20), 1 << 20) / double(1 << 20);
  return std::ldexp(m, *rc::gen::inRange(lo, hi + 1));
}

}  // namespace

TEST_CASE("disjoint balls: the obvious cases") {
  const Point3 o{0, 0, 0};
  CHECK(certified(o, 1, {3, 0, 0}, 1));          // apart
  CHECK(certified(o, 4, {0, 3, 4}, 4));          // |d| = 5 > 2 + 2
  CHECK_FALSE(certified(o, 4, {0, 3, 4}, 9));    // touching: 5 = 2 + 3
  CHECK_FALSE(certified(o, 4, {0, 3, 4}, 16));   // overlapping
  CHECK_FALSE(certified(o, 0, o, 0));            // the same point
  CHECK(certified(o, 0, {1e-3, 0, 0}, 0));       // two distinct points (radius 0)
  CHECK_FALSE(certified(o, -1, {10, 0, 0}, 1));  // an imaginary ball: never claimed
  CHECK_FALSE(certified(o, std::numeric_limits<double>::quiet_NaN(), {10, 0, 0}, 1));
  CHECK(std::isnan(radius_upper_bound(-1e-300)));
  CHECK(radius_upper_bound(4) > 2);
  CHECK(radius_upper_bound(0) > 0);
}

TEST_CASE("disjoint balls: sound on random balls, complete when clearly apart") {
  rc::prop("random centres and weights over many magnitudes", [] {
    const int e = *rc::gen::inRange(-300, 300);
    const Point3 a{scaled(e - 4, e), scaled(e - 4, e), scaled(e - 4, e)};
    const Point3 b{scaled(e - 4, e), scaled(e - 4, e), scaled(e - 4, e)};
    const double wa = std::fabs(scaled(2 * e - 12, 2 * e));
    const double wb = std::fabs(scaled(2 * e - 12, 2 * e));
    if (certified(a, wa, b, wb)) RC_ASSERT(exactly_disjoint(a, wa, b, wb));
  });
  rc::prop("balls within a few ulps of touching", [] {
    const int e = *rc::gen::inRange(-200, 200);
    const double ra = std::ldexp(*rc::gen::inRange(1, 1 << 20) / double(1 << 20), e);
    const double rb = std::ldexp(*rc::gen::inRange(1, 1 << 20) / double(1 << 20), e);
    // b at distance (ra + rb)(1 + k 2^-52) along a random direction (rounded), k within
    // a few ulps or around the test's margin (2^-40 = 4096 · 2^-52).
    const double k = *rc::gen::inRange(-64, 65) * *rc::gen::element(1.0, 64.0, 4096.0);
    std::array<double, 3> dir{};
    double len = 0;
    do {
      for (double& x : dir) x = *rc::gen::inRange(-1000, 1001) / 1000.0;
      len = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    } while (len < 0.1);
    const double dist = (ra + rb) * (1 + k * 0x1p-52);
    const Point3 a{std::ldexp(1.0, e), 0, 0};
    const Point3 b{a[0] + dir[0] / len * dist, dir[1] / len * dist, dir[2] / len * dist};
    const double wa = ra * ra;
    const double wb = rb * rb;
    if (certified(a, wa, b, wb)) RC_ASSERT(exactly_disjoint(a, wa, b, wb));
  });
  rc::prop("clearly apart (gap at least 1e-6 of the radii) is always certified", [] {
    const int e = *rc::gen::inRange(-200, 200);
    const Point3 a{scaled(e - 2, e), scaled(e - 2, e), scaled(e - 2, e)};
    const double ra = std::fabs(scaled(e - 8, e));
    const double rb = std::fabs(scaled(e - 8, e));
    const double factor = 1 + *rc::gen::inRange(1, 1000000) * 1e-6;
    const double dist = (ra + rb) * factor + std::ldexp(1.0, e - 30);
    const Point3 b{a[0], a[1] + dist, a[2]};
    RC_ASSERT(certified(a, ra * ra, b, rb * rb));
  });
}

TEST_CASE("disjoint balls imply a positive orthosphere power") {
  rc::prop("random balls of moderate size", [] {
    const Point3 a{scaled(-4, 2), scaled(-4, 2), scaled(-4, 2)};
    const Point3 b{scaled(-4, 2), scaled(-4, 2), scaled(-4, 2)};
    const double wa = std::fabs(scaled(-12, 2));
    const double wb = std::fabs(scaled(-12, 2));
    RC_PRE(!(a == b));
    const std::array<WeightedPoint, 2> pair{WeightedPoint{a, wa}, WeightedPoint{b, wb}};
    if (certified(a, wa, b, wb)) RC_ASSERT(orthosphere_power_sign(pair) == Sign::positive);
  });
}
