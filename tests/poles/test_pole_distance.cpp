#include "rstruct/poles/pole_distance.hpp"

#include <catch2/catch.hpp>
#include <chrono>
#include <random>
#include <rapidcheck/catch.h>
#include <thread>
#include <vector>

#include "rstruct/core/error.hpp"
#include "rstruct/poles/pole_analysis.hpp"

using rstruct::Point3;
using rstruct::poles::pole_distance;
using rstruct::poles::pole_distance_brute_force;

namespace {

std::vector<Point3> random_points(std::mt19937_64& rng, std::size_t n, double offset,
                                  double scale) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Point3> points(n);
  for (auto& p : points) p = Point3{offset + scale * u(rng), offset + scale * u(rng), scale * u(rng)};
  return points;
}

}  // namespace

TEST_CASE("D̂ by kd-tree equals the brute-force distance to the nearest pole") {
  rc::prop("kd-tree vs brute force", [] {
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    const auto n = *rc::gen::inRange<std::size_t>(1, 300);
    const auto m = *rc::gen::inRange<std::size_t>(1, 300);
    const double offset = *rc::gen::element(0.0, 1e6, -3.5e8);
    const double scale = *rc::gen::element(1.0, 1e-3, 250.0);
    RC_LOG() << "seed " << seed << "\n";
    std::mt19937_64 rng(seed);
    const auto points = random_points(rng, n, offset, scale);
    const auto poles = random_points(rng, m, offset, scale);
    const unsigned threads = *rc::gen::element(1U, 2U, 0U);
    const auto fast = pole_distance(points, poles, threads);
    const auto slow = pole_distance_brute_force(points, poles);
    RC_ASSERT(fast.distance.size() == n);
    for (std::size_t i = 0; i < n; ++i) {
      // The tree computes squared distances as rstruct::squared_distance does and breaks
      // ties by index, as the scan does: the same pole, the same double.
      RC_ASSERT(fast.nearest[i] == slow.nearest[i]);
      RC_ASSERT(fast.distance[i] == slow.distance[i]);
      RC_ASSERT(rstruct::distance(points[i], poles[fast.nearest[i]]) == fast.distance[i]);
    }
  });
}

TEST_CASE("D̂ of a point that is a pole is zero, and duplicates are harmless") {
  const std::vector<Point3> poles = {{0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {0x1p-1074, 0, 0}};
  const std::vector<Point3> points = {{1, 0, 0}, {0.25, 0, 0}, {-3, 4, 0}};
  const auto d = pole_distance(points, poles);
  CHECK(d.distance[0] == 0.0);
  CHECK(d.nearest[0] == 2);
  CHECK(d.distance[1] == 0.25);
  CHECK(d.distance[2] == 5.0);
}

TEST_CASE("D̂ input errors") {
  const std::vector<Point3> none;
  const std::vector<Point3> one = {{0, 0, 0}};
  const std::vector<Point3> bad = {{0, std::numeric_limits<double>::quiet_NaN(), 0}};
  CHECK_THROWS_AS(pole_distance(one, none), rstruct::InvalidInput);
  CHECK_THROWS_AS(pole_distance(bad, one), rstruct::InvalidInput);
  CHECK_THROWS_AS(pole_distance(one, bad), rstruct::InvalidInput);
  CHECK(pole_distance(none, none).distance.empty());
}

TEST_CASE("D̂ beside a side task: the task runs once and the distances do not change") {
  // 20,000 samples on a sphere: ten blocks of queries, so that the workers share them.
  std::mt19937_64 rng(7);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<Point3> samples(20000);
  for (auto& p : samples) p = rstruct::normalized(rstruct::Vec3{g(rng), g(rng), g(rng)});
  rstruct::poles::PoleAnalysisOptions options;
  options.threads = 1;
  rstruct::poles::PoleAnalysis analysis = rstruct::poles::analyse_poles(samples, options);
  const auto reference = pole_distance(samples, analysis.poles, 1);
  for (const unsigned threads : {1U, 2U, 3U}) {
    for (const int delay_ms : {0, 30}) {
      int runs = 0;
      const auto d = rstruct::poles::pole_distance_beside(samples, analysis.poles, threads, [&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
        ++runs;
      });
      CHECK(runs == 1);
      CHECK(d.distance == reference.distance);  // bitwise: the same searches
      CHECK(d.nearest == reference.nearest);
    }
    CHECK_THROWS_WITH(rstruct::poles::pole_distance_beside(
                          samples, analysis.poles, threads,
                          [] { throw rstruct::InvalidInput("side task failed"); }),
                      "side task failed");
  }
  int runs = 0;
  CHECK(rstruct::poles::pole_distance_beside({}, rstruct::poles::PoleSet{}, 2, [&] { ++runs; })
            .distance.empty());
  CHECK(runs == 1);
}
