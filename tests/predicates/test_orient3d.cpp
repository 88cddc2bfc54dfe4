// orient3d and coplanar_orientation against the rational oracle, and metamorphic
// properties (permutations, exact translations, power-of-two scalings).
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

TEST_CASE("orient3d convention: positive for the right-handed unit tetrahedron") {
  CHECK(pr::orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}) == Sign::positive);
  CHECK(pr::orient3d({0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}) == Sign::negative);
  CHECK(pr::orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}) == Sign::zero);
}

TEST_CASE("orient3d agrees with the rational oracle on every input family") {
  const std::uint64_t seed = 0x5eed0001;
  INFO("seed " << seed);
  std::mt19937_64 rng(seed);
  for (int f = 0; f < static_cast<int>(Family::count_); ++f) {
    const auto fam = static_cast<Family>(f);
    INFO("family " << family_name(fam));
    int zeros = 0;
    for (int n = 0; n < 1500; ++n) {
      const auto p = make_points<4>(rng, fam);
      const int expected = oracle::orient3d(p[0], p[1], p[2], p[3]);
      const int got = to_int(pr::orient3d(p[0], p[1], p[2], p[3]));
      if (got != expected) {
        std::printf("orient3d mismatch: %a %a %a | %a %a %a | %a %a %a | %a %a %a\n", p[0].x,
                    p[0].y, p[0].z, p[1].x, p[1].y, p[1].z, p[2].x, p[2].y, p[2].z, p[3].x,
                    p[3].y, p[3].z);
      }
      REQUIRE(got == expected);
      zeros += expected == 0;
    }
    if (fam == Family::coplanar || fam == Family::collinear) CHECK(zeros == 1500);
  }
}

TEST_CASE("orient3d rejects non-finite input with InvalidInput") {
  const double inf = HUGE_VAL, nan = std::nan("");
  CHECK_THROWS_AS(pr::orient3d({inf, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}), InvalidInput);
  CHECK_THROWS_AS(pr::orient3d({nan, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}), InvalidInput);
  CHECK_THROWS_AS(pr::orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, -inf}), InvalidInput);
}

TEST_CASE("orient3d flips under odd permutations, is invariant under even ones") {
  rc::prop("permutations", [](std::uint64_t seed, unsigned family) {
    std::mt19937_64 rng(seed);
    const auto p = make_points<4>(rng, static_cast<Family>(family % int(Family::count_)));
    const Sign s = pr::orient3d(p[0], p[1], p[2], p[3]);
    RC_ASSERT(pr::orient3d(p[1], p[0], p[2], p[3]) == -s);
    RC_ASSERT(pr::orient3d(p[0], p[2], p[1], p[3]) == -s);
    RC_ASSERT(pr::orient3d(p[0], p[1], p[3], p[2]) == -s);
    RC_ASSERT(pr::orient3d(p[1], p[2], p[0], p[3]) == s);
    RC_ASSERT(pr::orient3d(p[1], p[0], p[3], p[2]) == s);
    RC_ASSERT(pr::orient3d(p[3], p[2], p[1], p[0]) == s);
  });
}

TEST_CASE("orient3d is invariant under exact translations and power-of-two scalings") {
  rc::prop("translation and scaling", [](std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    // Coordinates k·2^-30 with |k| < 2^40 and offsets m·2^-30 with |m| < 2^40: all sums
    // are exact.
    std::uniform_int_distribution<std::int64_t> k(-(std::int64_t{1} << 40), std::int64_t{1} << 40);
    auto coord = [&] { return std::ldexp(static_cast<double>(k(rng)), -30); };
    std::array<Point3, 4> p;
    for (auto& q : p) q = {coord(), coord(), coord()};
    if (seed % 3 == 0) p[3] = p[0] + (p[1] - p[0]) + (p[2] - p[0]);  // often coplanar
    const Vec3 t{coord(), coord(), coord()};
    const Sign s = pr::orient3d(p[0], p[1], p[2], p[3]);
    RC_ASSERT(s == static_cast<Sign>(oracle::orient3d(p[0], p[1], p[2], p[3])));
    RC_ASSERT(pr::orient3d(p[0] + t, p[1] + t, p[2] + t, p[3] + t) == s);
    const int e = *rc::gen::inRange(-900, 900);
    RC_ASSERT(pr::orient3d(scale_pow2(p[0], e), scale_pow2(p[1], e), scale_pow2(p[2], e),
                           scale_pow2(p[3], e)) == s);
  });
}

TEST_CASE("coplanar_orientation is the in-plane side test, projection independent") {
  rc::prop("against the 3D orientation with the plane normal", [](std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<int> small(-9, 9);
    auto vec = [&] { return Vec3{double(small(rng)), double(small(rng)), double(small(rng))}; };
    const Vec3 o = vec(), u = vec(), v = vec();
    RC_PRE(squared_norm(cross(u, v)) > 0);
    const auto pts = coplanar_points(rng, 4, o, u, v, 5);
    RC_PRE(squared_norm(cross(pts[1] - pts[0], pts[2] - pts[0])) > 0);
    const Vec3 n = cross(pts[1] - pts[0], pts[2] - pts[0]);  // exact: small integers
    // d on the side of c iff orient3d(a, b, a + n, d) has the sign of orient3d(a, b, a + n, c).
    const Point3 an = pts[0] + n;
    const Sign expected = pr::orient3d(pts[0], pts[1], an, pts[3]) *
                          pr::orient3d(pts[0], pts[1], an, pts[2]);
    RC_ASSERT(pr::coplanar_orientation(pts[0], pts[1], pts[2], pts[3]) == expected);
    // Permuting coordinate axes (an isometry) does not change it.
    auto swap_xy = [](Point3 p) { return Point3{p.y, p.x, p.z}; };
    RC_ASSERT(pr::coplanar_orientation(swap_xy(pts[0]), swap_xy(pts[1]), swap_xy(pts[2]),
                                       swap_xy(pts[3])) == expected);
  });
  CHECK_THROWS_AS(pr::coplanar_orientation({0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {0, 1, 0}),
                  InvalidInput);
}
