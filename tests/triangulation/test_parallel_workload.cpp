// The parallel passes do the work: they take most of the points and insert most of those
// themselves, leaving few to the sequential insertion after them. With vertex locks (points
// on a surface) how many a worker defers depends on timing: a worker descheduled while it
// holds locks makes the other defer the points that need them. So this test runs alone
// (meson: is_parallel false) and only builds the parallel triangulations; that they equal the
// sequential ones is test_parallel_insertion's.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "generators.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"

namespace {

using rstruct::Point3;
using rstruct::test::Input;
using rstruct::test::torus_points;
using rstruct::triangulation::TriangulationOptions;
using rstruct::triangulation::TriangulationStats;

using Scheme = TriangulationOptions::ParallelScheme;

TriangulationStats parallel_stats(const Input& in, unsigned threads, Scheme scheme,
                                  std::size_t insert_first = 0) {
  TriangulationOptions options;
  options.threads = threads;
  options.parallel_min_round = 2000;
  options.parallel_scheme = scheme;
  options.insert_first = insert_first;
  const auto t = rstruct::test::build(in, options);
  const TriangulationStats s = t.stats();
  INFO(in.points.size() << " points, " << threads << " threads, scheme "
                        << static_cast<int>(scheme) << ": " << s.parallel_points
                        << " to the passes, " << s.deferred_points << " deferred");
  CHECK(s.threads == threads);
  return s;
}

/// Most points went to the passes, which inserted `share` of them themselves at least.
TriangulationStats check_busy(const Input& in, unsigned threads, Scheme scheme, double share) {
  const TriangulationStats s = parallel_stats(in, threads, scheme);
  CHECK(s.parallel_points > in.points.size() / 2);
  CHECK(static_cast<double>(s.deferred_points) <
        (1 - share) * static_cast<double>(s.parallel_points));
  return s;
}

}  // namespace

TEST_CASE("uniform points: fixed borders, two passes") {
  const Input in{rstruct::test::uniform_points(40000, 11), {}};
  // Two workers: every pass with fixed borders (the second cuts across the first one's
  // borders). Three: pass 1 of the 20,000-point round defers more than a quarter of it
  // (its stretches are small, so a large share of their points lies near a border) and
  // that round turns to locks; deterministic, since a pass with fixed borders does not
  // depend on timing.
  const TriangulationStats two = check_busy(in, 2, Scheme::automatic, 2.0 / 3);
  CHECK(two.border_passes >= 2);
  CHECK(two.lock_passes == 0);
  check_busy(in, 3, Scheme::automatic, 2.0 / 3);
}

TEST_CASE("points on a torus: locks after the first large pass") {
  const Input in{torus_points(30000, 5), {}};
  const TriangulationStats automatic = check_busy(in, 2, Scheme::automatic, 2.0 / 3);
  // Fixed borders until a large round defers a quarter, then locks.
  CHECK(automatic.border_passes >= 1);
  CHECK(automatic.lock_passes >= 1);
  const std::size_t n = 30000;
  const Input weighted{torus_points(n, 12), rstruct::test::hiding_weights(n, 2e-3, 13)};
  for (const unsigned threads : {2u, 3u}) {
    const TriangulationStats s = check_busy(weighted, threads, Scheme::locks, 2.0 / 3);
    CHECK(s.border_passes == 0);
    CHECK(s.lock_passes >= 1);
  }
}

TEST_CASE("points on a torus: a point kept out by the other worker's locks is tried again") {
  // The other worker holds those locks only until its insertion ends, so the point is tried
  // again at once (Builder::run_worker). 1.2·10^5 torus points: more than the 10^5 up to
  // which -Dchecks=expensive validates each triangulation (10 s a run here; validity is
  // test_parallel_insertion's). Two workers, share deferred over three runs (2026-12-05):
  // without the immediate retries
  // 1.4-1.6 % (debugoptimized), 0.58-0.70 % (sanitizers); with them 0.13-0.25 % and
  // 0.12-0.26 %. The best of three runs is checked: a worker descheduled by the host holds
  // its locks for milliseconds, and one such run deferred enough to lift the sum of three
  // over the bound (CI on ab0c079, sanitizers, the test alone: 2,194 of 354,327, 0.62 %),
  // while without the retries every run defers more than 0.5 %.
  const Input in{torus_points(120000, 31), {}};
  double best = 1.0;
  for (int run = 0; run < 3; ++run) {
    const TriangulationStats s = parallel_stats(in, 2, Scheme::locks);
    INFO("run " << run << ": " << s.deferred_points << " of " << s.parallel_points << " deferred");
    CHECK(s.parallel_points > in.points.size() / 2);
    best = std::min(best, static_cast<double>(s.deferred_points) /
                              static_cast<double>(std::max<std::size_t>(1, s.parallel_points)));
  }
  INFO("best share " << best);
  CHECK(best < 0.005);
}

TEST_CASE("locks in a volume: uniform points with duplicates, a grid") {
  check_busy(rstruct::test::with_duplicates(30000, 14, 3000), 2, Scheme::locks, 0.9);
  check_busy({rstruct::test::grid_points(24, 24, 24), {}}, 2, Scheme::locks, 0.9);
}

TEST_CASE("shared points inserted first, with locks") {
  const Input corners = rstruct::test::torus_with_box_corners();
  for (const unsigned threads : {2u, 3u}) {
    for (const Scheme scheme : {Scheme::automatic, Scheme::locks}) {
      CHECK(parallel_stats(corners, threads, scheme, 8).parallel_points >
            corners.points.size() / 2);
    }
  }
  const Input half{rstruct::test::uniform_points(30000, 21), {}};
  for (const unsigned threads : {2u, 3u}) {
    CHECK(parallel_stats(half, threads, Scheme::locks, 15000).parallel_points >
          (half.points.size() - 15000) / 2);
  }
}

TEST_CASE("locks: a stretch needing more new cells per point than the average has them") {
  // Half the points on a torus (long cells), half in a cube with weights that hide many of
  // them (few cells per point), the two apart along one axis: along the axis the Hilbert
  // curve splits first, one worker's stretch holds the torus. With locks the workers' new
  // cells come from one pool (Builder::parallel_pass). With a region per worker sized by
  // the average cells per point, workers ran out in each of 3 runs (along axis 0 in every
  // run, in two runs along every axis), and a worker that runs out leaves the rest to its
  // partner.
  const std::size_t half = 20000;
  for (std::size_t axis = 0; axis < 3; ++axis) {
    Input in{torus_points(half, 51), {}};
    for (Point3& p : in.points) p[axis] -= 3;
    for (Point3 p : rstruct::test::uniform_points(half, 52)) {
      for (std::size_t a = 0; a < 3; ++a) p[a] *= 2.6;
      p[axis] += 3;
      in.points.push_back(p);
    }
    in.weights.assign(half, 0.0);
    for (const double w : rstruct::test::hiding_weights(half, 0.05, 53)) in.weights.push_back(w);
    const TriangulationStats s = parallel_stats(in, 2, Scheme::locks);
    INFO("axis " << axis << ": " << s.exhausted_workers << " workers ran out; "
                 << s.deferred_points << " of " << s.parallel_points << " deferred");
    CHECK(s.exhausted_workers == 0);
    CHECK(s.parallel_points > in.points.size() / 2);
    CHECK(s.deferred_points * 20 < s.parallel_points);
  }
}
