// The stages separately: each filter, when it decides, agrees with the exact stage alone
// (Shewchuk's rule: a checker never shares the approximations of the code it checks);
// the counters count the stage that decided (when built with -Dcounters=true).
#include <rapidcheck/catch.h>

#include <catch2/catch.hpp>
#include <random>

#include "predicates/cases.hpp"
#include "predicates/exact_stage.hpp"
#include "rstruct/predicates/detail/filters.hpp"
#include "rstruct/predicates/counters.hpp"
#include "rstruct/predicates/predicates.hpp"

using namespace rstruct;
using namespace rstruct::testing;
namespace pr = rstruct::predicates;
namespace pd = rstruct::predicates::detail;

TEST_CASE("every filter decision equals the exact stage's sign") {
  const std::uint64_t seed = 0x5eed0008;
  INFO("seed " << seed);
  std::mt19937_64 rng(seed);
  long decided = 0, total = 0;
  for (int f = 0; f < static_cast<int>(Family::count_); ++f) {
    const auto fam = static_cast<Family>(f);
    INFO("family " << family_name(fam));
    for (int n = 0; n < 2000; ++n) {
      const auto p = make_weighted<5>(rng, fam);
      const auto check = [&](int filtered, int exact) {
        ++total;
        if (filtered == pd::kUndecided) return;
        ++decided;
        REQUIRE(filtered == exact);
      };
      check(pd::orient3d_filter(p[0].c, p[1].c, p[2].c, p[3].c),
            pd::orient3d_exact(p[0].c, p[1].c, p[2].c, p[3].c));
      check(pd::lifted4_filter<true>(p[0], p[1], p[2], p[3], p[4]),
            pd::lifted4_exact(p[0], p[1], p[2], p[3], p[4]));
      const WeightedPoint u[5] = {{p[0].c}, {p[1].c}, {p[2].c}, {p[3].c}, {p[4].c}};
      check(pd::lifted4_filter<false>(u[0], u[1], u[2], u[3], u[4]),
            pd::lifted4_exact(u[0], u[1], u[2], u[3], u[4]));
      for (int k = 0; k < 3; ++k) {
        check(pd::orient2d_filter(p[0].c, p[1].c, p[2].c, k),
              pd::orient2d_exact(p[0].c, p[1].c, p[2].c, k));
        check(pd::coplanar_power_filter(p[0], p[1], p[2], p[3], k),
              pd::coplanar_power_exact(p[0], p[1], p[2], p[3], k));
        check(pd::collinear_power_filter(p[0], p[1], p[2], k),
              pd::collinear_power_exact(p[0], p[1], p[2], k));
      }
      check(pd::squared_distance_difference_filter(p[0].c, p[1].c, p[2].c),
            pd::squared_distance_difference_exact(p[0].c, p[1].c, p[2].c));
      check(pd::power_difference_filter(p[0].c, p[1], p[2]),
            pd::power_difference_exact(p[0].c, p[1], p[2]));
      check(pd::power_value_filter(p[0].c, p[1]), pd::power_value_exact(p[0].c, p[1]));
      check(pd::ball_side_filter(p[0].c, p[1].c, p[2].w), pd::ball_side_exact(p[0].c, p[1].c, p[2].w));
    }
  }
  CHECK(decided > total / 3);
}

TEST_CASE("the filters decide random inputs and give up on degenerate ones") {
  std::mt19937_64 rng(0x5eed0009);
  int undecided_random = 0, undecided_degenerate = 0;
  for (int n = 0; n < 10000; ++n) {
    const auto p = make_points<5>(rng, Family::uniform);
    undecided_random += pd::orient3d_filter(p[0], p[1], p[2], p[3]) == pd::kUndecided;
    const auto q = make_points<5>(rng, Family::cospherical);
    if (pd::orient3d_exact(q[0], q[1], q[2], q[3]) == 0) continue;
    undecided_degenerate += pd::lifted4_filter<false>({q[0]}, {q[1]}, {q[2]}, {q[3]}, {q[4]}) ==
                            pd::kUndecided;
  }
  CHECK(undecided_random == 0);
  CHECK(undecided_degenerate > 1000);  // exactly cospherical: zero, never decided
}

TEST_CASE("stage counters count the deciding stage") {
  pr::reset_stage_counts();
  const Point3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0}, d{0, 0, 1}, on{1, 1, 0}, in{0.25, 0.25, 0.25};
  CHECK(pr::orient3d(a, b, c, d) == Sign::positive);       // filter
  CHECK(pr::orient3d(a, b, c, on) == Sign::zero);          // exact (zero)
  CHECK(pr::insphere(a, b, c, d, in) == Sign::positive);   // filter
  CHECK(pr::insphere_sos(a, b, c, d, on, 0, 1, 2, 3, 4) != Sign::zero);  // perturbed
  const auto o = pr::stage_counts(pr::PredicateId::orient3d);
  const auto s = pr::stage_counts(pr::PredicateId::insphere);
  if (pr::counters_enabled()) {
    CHECK(o.filter >= 1);
    CHECK(o.exact >= 1);
    CHECK(s.filter == 1);
    CHECK(s.perturbed == 1);
    CHECK(s.exact == 0);
  } else {
    CHECK(o.total() == 0);
    CHECK(s.total() == 0);
  }
  CHECK(std::string(pr::predicate_name(pr::PredicateId::power_test)) == "power_test");
  pr::reset_stage_counts();
  CHECK(pr::stage_counts(pr::PredicateId::orient3d).total() == 0);
}
