// Power tests inside a plane and on a line, unperturbed and perturbed, against the
// rational oracle (orthocircle / orthosegment; 3D constructions for the perturbation),
// and independence from the coordinate plane used internally.
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

namespace {

/// Four weighted coplanar points with small integer data; weights often orthogonal to one
/// circle (exactly degenerate), sometimes zero, sometimes cocircular points.
std::array<WeightedPoint, 4> coplanar_case(std::mt19937_64& rng) {
  // Small integers (exact everywhere), or large ones (up to 2^24: the lifted heights and
  // orthogonal weights round in double, so cases are nearly, not exactly, degenerate and
  // the filter has to give up).
  const bool large = rng() % 2 == 0;
  std::uniform_int_distribution<int> small(large ? -(1 << 24) : -6, large ? 1 << 24 : 6);
  auto vec = [&] { return Vec3{double(small(rng)), double(small(rng)), double(small(rng))}; };
  Vec3 u = vec(), v = vec();
  while (squared_norm(cross(u, v)) == 0) {
    u = vec();
    v = vec();
  }
  const auto pts = coplanar_points(rng, 4, vec(), u, v, 4);
  std::array<WeightedPoint, 4> p;
  const int kind = static_cast<int>(rng() % 3);
  std::uniform_int_distribution<int> tiny(-6, 6);
  const Point3 z = pts[0] + double(tiny(rng)) * u + double(tiny(rng)) * v;
  for (std::size_t i = 0; i < 4; ++i) {
    p[i].c = pts[i];
    p[i].w = kind == 0 ? 0.0 : (kind == 1 ? double(tiny(rng)) : squared_distance(pts[i], z) - 3);
  }
  return p;
}

Point3 swap_xz(const Point3& p) { return {p.z, p.y, p.x}; }

}  // namespace

TEST_CASE("coplanar power tests agree with the rational oracle") {
  const std::uint64_t seed = 0x5eed0005;
  INFO("seed " << seed);
  std::mt19937_64 rng(seed);
  int zeros = 0;
  for (int n = 0; n < 4000; ++n) {
    const auto p = coplanar_case(rng);
    if (squared_norm(cross(p[1].c - p[0].c, p[2].c - p[0].c)) == 0) continue;
    const int expected = oracle::coplanar_power_test(p[0], p[1], p[2], p[3]);
    REQUIRE(to_int(pr::coplanar_power_test(p[0], p[1], p[2], p[3])) == expected);
    zeros += expected == 0;
    std::array<std::uint32_t, 4> ids{std::uint32_t(rng() % 100), 0, 0, 0};
    ids[1] = ids[0] + 1 + std::uint32_t(rng() % 5);
    ids[2] = ids[1] + 1 + std::uint32_t(rng() % 5);
    ids[3] = ids[2] + 1 + std::uint32_t(rng() % 5);
    std::shuffle(ids.begin(), ids.end(), rng);
    const Sign s = pr::coplanar_power_test_sos(p[0], p[1], p[2], p[3], ids[0], ids[1], ids[2], ids[3]);
    REQUIRE(s != Sign::zero);
    REQUIRE(to_int(s) == oracle::coplanar_power_test_sos(p, ids));
    if (expected != 0) REQUIRE(to_int(s) == expected);
    // Independent of the coordinate plane: swapping axes is an isometry.
    std::array<WeightedPoint, 4> q = p;
    for (auto& x : q) x.c = swap_xz(x.c);
    REQUIRE(pr::coplanar_power_test_sos(q[0], q[1], q[2], q[3], ids[0], ids[1], ids[2], ids[3]) == s);
    // Even permutation of the triangle keeps it, odd keeps it too (a circle test has no
    // orientation).
    REQUIRE(pr::coplanar_power_test_sos(p[1], p[0], p[2], p[3], ids[1], ids[0], ids[2], ids[3]) == s);
  }
  CHECK(zeros > 100);
}

TEST_CASE("collinear power tests agree with the rational oracle") {
  const std::uint64_t seed = 0x5eed0006;
  INFO("seed " << seed);
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> small(-6, 6), large(-(1 << 24), 1 << 24);
  int zeros = 0;
  for (int n = 0; n < 4000; ++n) {
    const Vec3 o{double(small(rng)), double(small(rng)), double(small(rng))};
    Vec3 u{double(small(rng)), double(small(rng)), double(small(rng))};
    if (n % 4 == 2) u = {double(large(rng)), double(large(rng)), double(large(rng))};
    if (squared_norm(u) == 0) u = {0, 0, 1};
    const auto pts = collinear_points(rng, 3, o, u, 4);
    if (pts[0] == pts[1]) continue;
    std::array<WeightedPoint, 3> p;
    const Point3 z = o + double(small(rng)) * u + Vec3{double(small(rng)), 0, 0};
    for (std::size_t i = 0; i < 3; ++i) {
      p[i].c = pts[i];
      p[i].w = (n % 2 == 0) ? squared_distance(pts[i], z) - 2 : double(small(rng));
    }
    const int expected = oracle::collinear_power_test(p[0], p[1], p[2]);
    REQUIRE(to_int(pr::collinear_power_test(p[0], p[1], p[2])) == expected);
    zeros += expected == 0;
    const std::array<std::uint32_t, 3> ids{std::uint32_t(n % 3), std::uint32_t((n + 1) % 3),
                                           std::uint32_t((n + 2) % 3) + 7};
    const Sign s = pr::collinear_power_test_sos(p[0], p[1], p[2], ids[0], ids[1], ids[2]);
    REQUIRE(s != Sign::zero);
    REQUIRE(to_int(s) == oracle::collinear_power_test_sos(p, ids));
    REQUIRE(pr::collinear_power_test_sos(p[1], p[0], p[2], ids[1], ids[0], ids[2]) == s);
  }
  CHECK(zeros > 200);
  CHECK_THROWS_AS(pr::collinear_power_test({{1, 2, 3}, 0}, {{1, 2, 3}, 1}, {{0, 0, 0}, 0}),
                  InvalidInput);
}

TEST_CASE("coincident power test: larger weight wins, then the smaller id") {
  const WeightedPoint a{{1, 2, 3}, 0.5}, e{{1, 2, 3}, 0.75};
  CHECK(pr::coincident_power_test_sos(a, e, 4, 9) == Sign::positive);
  CHECK(pr::coincident_power_test_sos(e, a, 9, 4) == Sign::negative);
  CHECK(pr::coincident_power_test_sos(a, a, 4, 9) == Sign::negative);
  CHECK(pr::coincident_power_test_sos(a, a, 9, 4) == Sign::positive);
  CHECK_THROWS_AS(pr::coincident_power_test_sos(a, a, 4, 4), InvalidInput);
}

TEST_CASE("coplanar_power_test rejects a collinear triangle") {
  CHECK_THROWS_AS(pr::coplanar_power_test({{0, 0, 0}}, {{1, 1, 1}}, {{2, 2, 2}}, {{0, 1, 0}}),
                  InvalidInput);
}
