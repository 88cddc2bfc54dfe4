// The symbolically perturbed insphere and power tests: never zero, equal to the
// unperturbed sign when that is non-zero, equal to an independent rational evaluation of
// the perturbed determinant (polynomial in ε), consistent under permutations.
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

std::array<std::uint32_t, 5> random_ids(std::mt19937_64& rng) {
  std::array<std::uint32_t, 5> ids{};
  std::uniform_int_distribution<std::uint32_t> d(0, 40);
  for (std::size_t i = 0; i < 5; ++i) {
    bool fresh = false;
    while (!fresh) {
      ids[i] = d(rng);
      fresh = true;
      for (std::size_t j = 0; j < i; ++j) fresh = fresh && ids[j] != ids[i];
    }
  }
  return ids;
}

Sign sos(const std::array<WeightedPoint, 5>& p, const std::array<std::uint32_t, 5>& id,
         const std::array<int, 5>& perm) {
  auto P = [&](int i) -> const WeightedPoint& { return p[static_cast<std::size_t>(perm[i])]; };
  auto I = [&](int i) { return id[static_cast<std::size_t>(perm[i])]; };
  return pr::power_test_sos(P(0), P(1), P(2), P(3), P(4), I(0), I(1), I(2), I(3), I(4));
}

}  // namespace

TEST_CASE("power_test_sos agrees with the rational evaluation of the perturbed determinant") {
  const std::uint64_t seed = 0x5eed0004;
  INFO("seed " << seed);
  std::mt19937_64 rng(seed);
  int perturbed = 0;
  for (int f = 0; f < static_cast<int>(Family::count_); ++f) {
    const auto fam = static_cast<Family>(f);
    INFO("family " << family_name(fam));
    for (int n = 0; n < 800; ++n) {
      const auto p = make_weighted<5>(rng, fam);
      if (pr::orient3d(p[0].c, p[1].c, p[2].c, p[3].c) == Sign::zero) continue;
      const auto ids = random_ids(rng);
      const int expected = oracle::power_test_sos(p, ids);
      const Sign got = pr::power_test_sos(p[0], p[1], p[2], p[3], p[4], ids[0], ids[1], ids[2],
                                          ids[3], ids[4]);
      REQUIRE(got != Sign::zero);
      REQUIRE(to_int(got) == expected);
      const Sign plain = pr::power_test(p[0], p[1], p[2], p[3], p[4]);
      if (plain != Sign::zero) REQUIRE(got == plain);
      perturbed += plain == Sign::zero;
      if (p[0].w == 0 && p[1].w == 0 && p[2].w == 0 && p[3].w == 0 && p[4].w == 0) {
        REQUIRE(pr::insphere_sos(p[0].c, p[1].c, p[2].c, p[3].c, p[4].c, ids[0], ids[1], ids[2],
                                 ids[3], ids[4]) == got);
      }
    }
  }
  CHECK(perturbed > 100);  // the degenerate families really exercise the perturbation
}

TEST_CASE("perturbed results are consistent across permutations of the cell") {
  rc::prop("odd permutations flip, even keep", [](std::uint64_t seed, unsigned family) {
    std::mt19937_64 rng(seed);
    const auto p = make_weighted<5>(rng, static_cast<Family>(family % 6));
    RC_PRE(pr::orient3d(p[0].c, p[1].c, p[2].c, p[3].c) != Sign::zero);
    const auto ids = random_ids(rng);
    const Sign s = sos(p, ids, {0, 1, 2, 3, 4});
    RC_ASSERT(s != Sign::zero);
    RC_ASSERT(sos(p, ids, {1, 0, 2, 3, 4}) == -s);
    RC_ASSERT(sos(p, ids, {0, 1, 3, 2, 4}) == -s);
    RC_ASSERT(sos(p, ids, {2, 0, 1, 3, 4}) == s);
    RC_ASSERT(sos(p, ids, {3, 2, 1, 0, 4}) == s);
  });
}

TEST_CASE("Delaunay perturbation on exactly cospherical points: one consistent answer") {
  // Eight cospherical points (cube corners): each query against each positively oriented
  // cell is decided, and swapping which of two cospherical points is the query flips
  // consistently with the lifted determinant's antisymmetry.
  std::vector<Point3> cube;
  for (int i = 0; i < 8; ++i) cube.push_back({double(i & 1), double((i >> 1) & 1), double(i >> 2)});
  for (std::uint32_t a = 0; a < 8; ++a)
    for (std::uint32_t b = 0; b < 8; ++b)
      for (std::uint32_t c = 0; c < 8; ++c)
        for (std::uint32_t d = 0; d < 8; ++d)
          for (std::uint32_t e = 0; e < 8; ++e) {
            if (a == b || a == c || a == d || a == e || b == c || b == d || b == e || c == d ||
                c == e || d == e) {
              continue;
            }
            if (pr::orient3d(cube[a], cube[b], cube[c], cube[d]) != Sign::positive) continue;
            REQUIRE(pr::insphere(cube[a], cube[b], cube[c], cube[d], cube[e]) == Sign::zero);
            const Sign s = pr::insphere_sos(cube[a], cube[b], cube[c], cube[d], cube[e], a, b, c, d, e);
            REQUIRE(s != Sign::zero);
            const int expected = oracle::power_test_sos(
                {WeightedPoint{cube[a]}, {cube[b]}, {cube[c]}, {cube[d]}, {cube[e]}}, {a, b, c, d, e});
            REQUIRE(to_int(s) == expected);
          }
}

TEST_CASE("perturbed tests reject flat cells and repeated ids") {
  const WeightedPoint a{{0, 0, 0}}, b{{1, 0, 0}}, c{{0, 1, 0}}, d{{1, 1, 0}}, e{{2, 2, 0}};
  CHECK_THROWS_AS(pr::power_test_sos(a, b, c, d, e, 0, 1, 2, 3, 4), InvalidInput);
  const WeightedPoint d3{{0, 0, 1}}, onsphere{{1, 1, 1}};
  CHECK_THROWS_AS(pr::power_test_sos(a, b, c, d3, onsphere, 0, 1, 2, 3, 3), InvalidInput);
  CHECK(pr::power_test_sos(a, b, c, d3, onsphere, 0, 1, 2, 3, 4) != Sign::zero);
}
