#include "rstruct/poles/covering_sets.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <rapidcheck/catch.h>
#include <vector>

#include "rstruct/core/error.hpp"

using rstruct::Ball;
using rstruct::Point3;
using rstruct::poles::CoveringSets;
using rstruct::poles::covering_sets;
using rstruct::poles::covering_sets_brute_force;

namespace {

bool same(const CoveringSets& a, const CoveringSets& b) {
  return a.row_count == b.row_count && a.column_offsets == b.column_offsets && a.rows == b.rows;
}

}  // namespace

TEST_CASE("covering sets by kd-tree equal the brute force") {
  rc::prop("kd-tree vs brute force", [] {
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    RC_LOG() << "seed " << seed << "\n";
    std::mt19937_64 rng(seed);
    const auto n = *rc::gen::inRange<std::size_t>(0, 400);
    const auto m = *rc::gen::inRange<std::size_t>(0, 200);
    const double offset = *rc::gen::element(0.0, 1e6, -7.25e9);
    const double scale = *rc::gen::element(1.0, 1e-4, 3e3);
    // Integer grids make many points lie exactly on the balls' spheres.
    const bool grid = *rc::gen::arbitrary<bool>();
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::uniform_int_distribution<int> k(-4, 4);
    auto coordinate = [&] { return grid ? scale * k(rng) : scale * u(rng); };
    std::vector<Point3> points(n);
    for (auto& p : points) p = {offset + coordinate(), coordinate(), offset + coordinate()};
    std::vector<Ball> balls(m);
    for (auto& b : balls) {
      b.c = points.empty() || !grid ? Point3{offset + coordinate(), coordinate(), offset + coordinate()}
                                    : points[rng() % points.size()];
      b.r = grid ? scale * static_cast<double>(rng() % 4) : scale * std::fabs(u(rng));
    }
    const unsigned threads = *rc::gen::element(1U, 2U, 3U, 0U);
    const CoveringSets fast = covering_sets(balls, points, threads);
    const CoveringSets slow = covering_sets_brute_force(balls, points);
    RC_ASSERT(fast.is_valid());
    RC_ASSERT(slow.is_valid());
    RC_ASSERT(same(fast, slow));
  });
}

TEST_CASE("points exactly on a ball's sphere are covered, one ulp outside are not") {
  const Point3 c{1e6, -2e6, 0.5};
  const std::vector<Point3> on = {{1e6 + 3, -2e6 + 4, 0.5}, {1e6, -2e6, 5.5}, {1e6 - 5, -2e6, 0.5}};
  std::vector<Point3> points = on;
  points.push_back({std::nextafter(1e6 + 5, 2e6), -2e6, 0.5});
  points.push_back({1e6, -2e6, std::nextafter(-4.5, -5.0)});
  const std::vector<Ball> balls = {{c, 5.0}, {c, std::nextafter(5.0, 0.0)}, {c, 0.0}};
  const auto sets = covering_sets(balls, points, 1);
  REQUIRE(sets.is_valid());
  REQUIRE(sets.column_count() == 3);
  CHECK(std::vector<std::uint32_t>(sets.column(0).begin(), sets.column(0).end()) ==
        std::vector<std::uint32_t>{0, 1, 2});
  CHECK(sets.column(1).empty());
  CHECK(sets.column(2).empty());
  CHECK(sets.uncovered_row_count() == 2);
  CHECK(same(sets, covering_sets_brute_force(balls, points)));
}

TEST_CASE("a zero-radius ball covers exactly the points at its centre") {
  const std::vector<Point3> points = {{1, 2, 3}, {1, 2, 3}, {1, 2, std::nextafter(3.0, 4.0)}};
  const std::vector<Ball> balls = {{{1, 2, 3}, 0.0}};
  const auto sets = covering_sets(balls, points);
  CHECK(sets.entry_count() == 2);
  CHECK(sets.column(0)[0] == 0);
  CHECK(sets.column(0)[1] == 1);
}

TEST_CASE("covering sets input errors") {
  const std::vector<Point3> points = {{0, 0, 0}};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(covering_sets(std::vector<Ball>{{{0, 0, 0}, -1.0}}, points),
                  rstruct::InvalidInput);
  CHECK_THROWS_AS(covering_sets(std::vector<Ball>{{{0, 0, 0}, nan}}, points),
                  rstruct::InvalidInput);
  CHECK_THROWS_AS(covering_sets(std::vector<Ball>{{{nan, 0, 0}, 1.0}}, points),
                  rstruct::InvalidInput);
  CHECK_THROWS_AS(covering_sets(std::vector<Ball>{{{0, 0, 0}, 1.0}},
                                std::vector<Point3>{{0, nan, 0}}),
                  rstruct::InvalidInput);
}
