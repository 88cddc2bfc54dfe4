// Parallel insertion (TriangulationOptions::threads > 1), with fixed borders and with
// vertex locks: the triangulation is the same as the sequential one (same finite cells,
// hidden points and duplicates) and valid; with fixed borders the cell ids do not depend on
// timing, and in the canonical order (TriangulationOptions::canonical_order) the cell array
// is the same for every thread count and every run. Nothing here depends on timing, so it
// runs beside other tests; that the passes insert most points themselves with vertex locks
// (which does depend on the workers having the cores) is test_parallel_workload's.
#include <rapidcheck/catch.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <utility>

#include "generators.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"

namespace {

using rstruct::Point3;
using rstruct::test::cell_set;
using rstruct::triangulation::RegularTriangulation3;
using rstruct::triangulation::TriangulationOptions;
using rstruct::triangulation::TriangulationStats;

using rstruct::test::Input;
using rstruct::test::torus_points;
using rstruct::test::with_duplicates;

using Scheme = TriangulationOptions::ParallelScheme;

RegularTriangulation3 build(const Input& in, unsigned threads, std::size_t min_round,
                            Scheme scheme = Scheme::automatic, bool canonical = false,
                            std::size_t steal_gap = TriangulationOptions{}.parallel_steal_gap) {
  TriangulationOptions options;
  options.threads = threads;
  options.parallel_min_round = min_round;
  options.parallel_scheme = scheme;
  options.canonical_order = canonical;
  options.parallel_steal_gap = steal_gap;
  return rstruct::test::build(in, options);
}

/// Same cell array: the same ids, vertices in the same slots and the same neighbours.
bool same_cell_array(const RegularTriangulation3& a, const RegularTriangulation3& b) {
  if (a.cell_capacity() != b.cell_capacity()) return false;
  for (rstruct::triangulation::CellId c = 0; c < a.cell_capacity(); ++c) {
    if (a.is_cell(c) != b.is_cell(c)) return false;
    if (!a.is_cell(c)) continue;
    if (a.vertices(c) != b.vertices(c)) return false;
    for (int i = 0; i < 4; ++i) {
      if (a.neighbor(c, i) != b.neighbor(c, i)) return false;
    }
  }
  return true;
}

/// The canonical order's definition, checked cell by cell: no free cells; within a cell
/// the two smallest ids first, increasing, and the larger two after them; cells sorted by
/// their vertex ids.
bool is_canonical(const RegularTriangulation3& t) {
  std::array<std::uint32_t, 4> previous{};
  for (rstruct::triangulation::CellId c = 0; c < t.cell_capacity(); ++c) {
    if (!t.is_cell(c)) return false;
    const std::array<std::uint32_t, 4> v = t.vertices(c);
    if (!(v[0] < v[1] && v[1] < v[2] && v[1] < v[3])) return false;
    std::array<std::uint32_t, 4> sorted = v;
    std::sort(sorted.begin(), sorted.end());
    if (c > 0 && !(previous < sorted)) return false;
    previous = sorted;
  }
  return true;
}

std::vector<std::uint32_t> hidden_ids(const RegularTriangulation3& t) {
  std::vector<std::uint32_t> ids;
  for (const auto& h : t.hidden_points()) ids.push_back(h.point);
  return ids;
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> duplicate_pairs(const RegularTriangulation3& t) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (const auto& d : t.duplicate_points()) pairs.emplace_back(d.point, d.vertex);
  return pairs;
}

/// Compares the parallel construction with the sequential one; returns both statistics
/// (sequential, parallel).
std::pair<TriangulationStats, TriangulationStats> check_same(const Input& in, unsigned threads,
                                                             std::size_t min_round) {
  const RegularTriangulation3 one = build(in, 1, min_round);
  const RegularTriangulation3 many = build(in, threads, min_round);
  const auto report = many.is_valid();
  INFO(report.message);
  REQUIRE(report.ok);
  CHECK(many.number_of_vertices() == one.number_of_vertices());
  CHECK(many.number_of_finite_cells() == one.number_of_finite_cells());
  CHECK(cell_set(many) == cell_set(one));
  CHECK(hidden_ids(many) == hidden_ids(one));
  CHECK(duplicate_pairs(many) == duplicate_pairs(one));
  const auto& s = many.stats();
  CHECK(s.threads == std::min(threads, 8u));
  CHECK(s.parallel_points > 0);  // (how many, with locks, depends on timing)
  return {one.stats(), s};
}

}  // namespace

TEST_CASE("parallel insertion: uniform points, two and three threads") {
  const Input in{rstruct::test::uniform_points(40000, 11), {}};
  check_same(in, 2, 2000);
  check_same(in, 3, 2000);
}

TEST_CASE("parallel insertion: a grid (cospherical everywhere)") {
  const auto [one, two] = check_same({rstruct::test::grid_points(32, 32, 32), {}}, 2, 2000);
  // The workers' filter failures (every cospherical cell's test) are added to the totals:
  // nearly every point goes through a worker, so the total is close to the sequential
  // run's (1.02 times it; counting only the main thread's, 0.53).
  INFO("filter misses: one thread " << one.filter_misses << ", two " << two.filter_misses
                                    << ", parallel points " << two.parallel_points);
  CHECK(one.filter_misses > 0);
  CHECK(4 * two.filter_misses > 3 * one.filter_misses);
}

TEST_CASE("parallel insertion: points on a torus surface") {
  // Long cells cross the workers' borders: after the first large pass the construction
  // takes vertex locks (see builder.cpp), and then the passes insert most points.
  const Input in{torus_points(30000, 5), {}};
  check_same(in, 2, 2000);
  // With fixed borders only, it turns sequential instead, which must still be right.
  const RegularTriangulation3 one = build(in, 1, 2000);
  const RegularTriangulation3 borders = build(in, 2, 2000, Scheme::borders);
  CHECK(cell_set(borders) == cell_set(one));
  CHECK(borders.stats().deferred_points * 4 > borders.stats().parallel_points);
}

TEST_CASE("parallel insertion with locks: weighted points on a surface, some hidden") {
  const std::size_t n = 30000;
  Input in{torus_points(n, 12), rstruct::test::hiding_weights(n, 2e-3, 13)};
  const RegularTriangulation3 t = build(in, 2, 2000, Scheme::locks);
  CHECK(t.hidden_points().size() > 100);
  check_same(in, 2, 2000);
  check_same(in, 3, 2000);
}

TEST_CASE("locks: a thread done with its stretch takes its partner's points from the far end") {
  // Without the gap a thread takes its partner's points until the two meet, so nearly
  // every pass has some taken (how many depends on timing): 2 threads (one pair), 3 (a
  // pair and one alone) and 4 (two pairs), points on a surface, weighted with some hidden.
  const std::size_t n = 30000;
  const Input surface{torus_points(n, 41), {}};
  const Input weighted{torus_points(n, 42), rstruct::test::hiding_weights(n, 2e-3, 43)};
  std::uint64_t taken = 0;
  for (const Input& in : {surface, weighted}) {
    const RegularTriangulation3 one = build(in, 1, 2000);
    for (const unsigned threads : {2u, 3u, 4u}) {
      const RegularTriangulation3 many = build(in, threads, 2000, Scheme::locks, false, 0);
      const auto report = many.is_valid();
      INFO(threads << " threads: " << report.message);
      REQUIRE(report.ok);
      CHECK(cell_set(many) == cell_set(one));
      CHECK(hidden_ids(many) == hidden_ids(one));
      taken += many.stats().taken_points;
      CHECK(many.stats().taken_points < many.stats().parallel_points);
    }
  }
  CHECK(taken > 0);
}

TEST_CASE("parallel insertion with locks: uniform points, a grid, duplicates") {
  const Input in = with_duplicates(30000, 14, 3000);
  for (const Input& input : {in, Input{rstruct::test::grid_points(24, 24, 24), {}}}) {
    const RegularTriangulation3 one = build(input, 1, 2000);
    const RegularTriangulation3 locks = build(input, 2, 2000, Scheme::locks);
    const auto report = locks.is_valid();
    INFO(report.message);
    REQUIRE(report.ok);
    CHECK(cell_set(locks) == cell_set(one));
    CHECK(hidden_ids(locks) == hidden_ids(one));
    CHECK(duplicate_pairs(locks) == duplicate_pairs(one));
  }
}

TEST_CASE("parallel insertion: weighted points, some hidden") {
  const std::size_t n = 40000;
  const double spacing = std::cbrt(1.0 / static_cast<double>(n));
  Input in{rstruct::test::uniform_points(n, 3),
           rstruct::test::hiding_weights(n, 2 * spacing * spacing, 4)};
  const RegularTriangulation3 t = build(in, 2, 2000);
  CHECK(t.hidden_points().size() > 100);  // the comparison below is not between empty sets
  check_same(in, 2, 2000);
}

TEST_CASE("parallel insertion: exact duplicates") {
  const Input in = with_duplicates(30000, 8, 10000);
  const RegularTriangulation3 t = build(in, 2, 2000);
  CHECK(t.duplicate_points().size() >= 8000);
  check_same(in, 2, 2000);
}

/// `in` triangulated with its last `shared` points inserted first and shared by the
/// workers, on `threads` threads by `scheme`: valid, and the same cells as `one`.
RegularTriangulation3 build_sharing(const Input& in, std::size_t shared, unsigned threads,
                                    Scheme scheme, const RegularTriangulation3& one) {
  TriangulationOptions options;
  options.threads = threads;
  options.parallel_min_round = 2000;
  options.parallel_scheme = scheme;
  options.insert_first = shared;
  RegularTriangulation3 t = rstruct::test::build(in, options);
  const auto report = t.is_valid();
  INFO(report.message << " (" << threads << " threads, scheme " << static_cast<int>(scheme)
                      << ")");
  REQUIRE(report.ok);
  CHECK(cell_set(t) == cell_set(one));
  return t;
}

TEST_CASE("points inserted first (bounding-box corners), shared by the workers") {
  const Input in = rstruct::test::torus_with_box_corners();
  const RegularTriangulation3 one = build(in, 1, 2000);
  for (const Scheme scheme : {Scheme::automatic, Scheme::borders, Scheme::locks}) {
    for (const unsigned threads : {1u, 2u, 3u}) {
      const RegularTriangulation3 first = build_sharing(in, 8, threads, scheme, one);
      if (threads > 1 && scheme == Scheme::borders) {
        // With fixed borders the shares do not depend on timing (with locks they do: see
        // test_parallel_workload). Every cell outside the torus has a corner: corners owned
        // like the other points keep 13,108 of the 18,759 points of the parallel rounds out
        // of the parallel passes on two workers, shared 9,317.
        CHECK(first.stats().parallel_points > in.points.size() / 2);
        const auto deferred = first.stats().deferred_points;
        const auto parallel = first.stats().parallel_points;
        if (threads == 2) CHECK(deferred * 10 < parallel * 6);
      }
    }
  }
  // And they are the first ones inserted (after_insertion sees the insertion order).
  Input small{torus_points(300, 20), {}};
  small.points.insert(small.points.end(), in.points.end() - 8, in.points.end());
  TriangulationOptions options;
  options.insert_first = 8;
  std::vector<std::uint32_t> order;
  options.after_insertion = [&](const RegularTriangulation3&, std::uint32_t p) {
    order.push_back(p);
  };
  rstruct::test::build(small, options);
  REQUIRE(order.size() == 308);
  for (std::size_t i = 0; i < 8; ++i) CHECK(order[i] >= 300);
}

TEST_CASE("many shared points: the workers keep out of the cells they would share") {
  // Half of the points inserted first and shared: facets with three shared vertices,
  // across which two workers could reach the same cell at once, are everywhere (see
  // facet_is_shared).
  const Input in{rstruct::test::uniform_points(30000, 21), {}};
  const RegularTriangulation3 one = build(in, 1, 2000);
  for (const Scheme scheme : {Scheme::borders, Scheme::locks}) {
    for (const unsigned threads : {2u, 3u}) {
      const RegularTriangulation3 t = build_sharing(in, 15000, threads, scheme, one);
      if (scheme == Scheme::borders) {  // (with locks: test_parallel_workload)
        CHECK(t.stats().parallel_points > (in.points.size() - 15000) / 2);
      }
    }
  }
}

TEST_CASE("parallel insertion with fixed borders does not depend on timing") {
  const Input in{rstruct::test::uniform_points(30000, 6), {}};
  const RegularTriangulation3 a = build(in, 2, 2000, Scheme::borders);
  const RegularTriangulation3 b = build(in, 2, 2000, Scheme::borders);
  CHECK(same_cell_array(a, b));
}

TEST_CASE("the canonical order: the same cell array for every thread count and run") {
  const std::size_t n = 20000;
  for (const Input& in : {Input{torus_points(n, 16), {}},
                          Input{torus_points(n, 17), rstruct::test::hiding_weights(n, 2e-3, 18)}}) {
    const RegularTriangulation3 one = build(in, 1, 2000, Scheme::automatic, true);
    const auto report = one.is_valid();
    INFO(report.message);
    REQUIRE(report.ok);
    CHECK(is_canonical(one));
    CHECK(cell_set(one) == cell_set(build(in, 1, 2000)));
    CHECK(hidden_ids(one) == hidden_ids(build(in, 1, 2000)));
    for (const unsigned threads : {2u, 3u}) {
      const RegularTriangulation3 many = build(in, threads, 2000, Scheme::locks, true);
      CHECK(same_cell_array(many, one));
      CHECK(hidden_ids(many) == hidden_ids(one));
    }
    // Only after passes with locks: renumbered when locks were taken, not otherwise.
    TriangulationOptions options;
    options.threads = 2;
    options.parallel_min_round = 2000;
    options.canonical_order_after_locks = true;
    CHECK(same_cell_array(rstruct::test::build(in, options), one));
    options.parallel_scheme = Scheme::borders;
    CHECK_FALSE(is_canonical(rstruct::test::build(in, options)));
  }
}

TEST_CASE("parallel insertion equals sequential on degenerate inputs") {
  rc::prop("random, grid, few-plane, duplicate-heavy, weighted", [] {
    const int kind = *rc::gen::inRange(0, 5);
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    const auto n = static_cast<std::size_t>(*rc::gen::inRange(600, 3000));
    const unsigned threads = *rc::gen::inRange(2u, 5u);
    RC_TAG(kind);
    Input in;
    switch (kind) {
      case 0: in.points = rstruct::test::uniform_points(n, seed); break;
      case 1: in.points = rstruct::test::grid_points(14, 12, 10); break;
      case 2: in.points = rstruct::test::few_plane_points(n, 5, seed); break;
      case 3: in.points = rstruct::test::duplicate_points(n, 60, seed); break;
      default:
        in.points = rstruct::test::uniform_points(n, seed);
        in.weights = rstruct::test::hiding_weights(n, 0.01, seed ^ 3);
        break;
    }
    const bool locks = *rc::gen::arbitrary<bool>();
    RC_TAG(locks ? "locks" : "borders");
    TriangulationOptions sequential;
    sequential.canonical_order = true;
    TriangulationOptions parallel;
    parallel.threads = threads;
    parallel.parallel_min_round = 100;
    parallel.parallel_scheme = locks ? Scheme::locks : Scheme::borders;
    parallel.parallel_steal_gap = *rc::gen::element<std::size_t>(0, 64, 4096);
    parallel.canonical_order = true;
    const RegularTriangulation3 one = rstruct::test::build(in, sequential);
    const RegularTriangulation3 many = rstruct::test::build(in, parallel);
    const auto report = many.is_valid();
    RC_ASSERT(report.ok);
    RC_ASSERT(is_canonical(many));
    RC_ASSERT(same_cell_array(many, one));
    RC_ASSERT(hidden_ids(many) == hidden_ids(one));
    RC_ASSERT(duplicate_pairs(many) == duplicate_pairs(one));
  });
}
