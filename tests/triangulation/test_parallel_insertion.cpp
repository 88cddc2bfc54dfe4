// Parallel insertion (TriangulationOptions::threads > 1): the triangulation is the same as
// the sequential one (same finite cells, hidden points and duplicates), valid, built mostly
// by the parallel passes, and the same on every run (cell ids do not depend on timing).
#include <rapidcheck/catch.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "generators.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"

namespace {

using rstruct::Point3;
using rstruct::test::cell_set;
using rstruct::triangulation::RegularTriangulation3;
using rstruct::triangulation::TriangulationOptions;

using rstruct::test::Input;

RegularTriangulation3 build(const Input& in, unsigned threads, std::size_t min_round) {
  TriangulationOptions options;
  options.threads = threads;
  options.parallel_min_round = min_round;
  return rstruct::test::build(in, options);
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

/// Compares the parallel construction with the sequential one; `busy`: the parallel passes
/// must have inserted most points themselves.
void check_same(const Input& in, unsigned threads, std::size_t min_round, bool busy) {
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
  CHECK(s.parallel_points > 0);
  if (busy) {
    // The passes took most of the points and inserted two thirds of those themselves at
    // least (40,000 uniform points, three workers: 6 % deferred after both passes).
    CHECK(s.parallel_points > in.points.size() / 2);
    CHECK(s.deferred_points * 3 < s.parallel_points);
  }
}

std::vector<Point3> torus_points(std::size_t n, std::uint64_t seed) {
  rstruct::test::Random r(seed);
  std::vector<Point3> p(n);
  for (Point3& q : p) {
    const double u = 2 * std::numbers::pi * r.uniform();
    const double v = 2 * std::numbers::pi * r.uniform();
    q = {(1 + 0.3 * std::cos(v)) * std::cos(u), (1 + 0.3 * std::cos(v)) * std::sin(u),
         0.3 * std::sin(v)};
  }
  return p;
}

}  // namespace

TEST_CASE("parallel insertion: uniform points, two and three threads") {
  const Input in{rstruct::test::uniform_points(40000, 11), {}};
  check_same(in, 2, 2000, true);
  check_same(in, 3, 2000, true);
}

TEST_CASE("parallel insertion: a grid (cospherical everywhere)") {
  check_same({rstruct::test::grid_points(32, 32, 32), {}}, 2, 2000, true);
}

TEST_CASE("parallel insertion: points on a torus surface") {
  // Long cells cross the workers' borders: the construction turns sequential after the
  // first pass (see builder.cpp), which must still be right.
  check_same({torus_points(30000, 5), {}}, 2, 2000, false);
}

TEST_CASE("parallel insertion: weighted points, some hidden") {
  const std::size_t n = 40000;
  const double spacing = std::cbrt(1.0 / static_cast<double>(n));
  Input in{rstruct::test::uniform_points(n, 3),
           rstruct::test::hiding_weights(n, 2 * spacing * spacing, 4)};
  const RegularTriangulation3 t = build(in, 2, 2000);
  CHECK(t.hidden_points().size() > 100);  // the comparison below is not between empty sets
  check_same(in, 2, 2000, true);
}

TEST_CASE("parallel insertion: exact duplicates") {
  Input in{rstruct::test::uniform_points(30000, 8), {}};
  rstruct::test::Random r(9);
  for (int i = 0; i < 10000; ++i) {
    in.points.push_back(in.points[static_cast<std::size_t>(r.integer(0, 29999))]);
  }
  const RegularTriangulation3 t = build(in, 2, 2000);
  CHECK(t.duplicate_points().size() >= 8000);
  check_same(in, 2, 2000, true);
}

TEST_CASE("parallel insertion does not depend on timing") {
  const Input in{torus_points(30000, 6), {}};
  const RegularTriangulation3 a = build(in, 2, 2000);
  const RegularTriangulation3 b = build(in, 2, 2000);
  REQUIRE(a.cell_capacity() == b.cell_capacity());
  bool same = true;
  for (rstruct::triangulation::CellId c = 0; c < a.cell_capacity(); ++c) {
    same = same && a.is_cell(c) == b.is_cell(c) &&
           (!a.is_cell(c) || a.vertices(c) == b.vertices(c));
    for (int i = 0; i < 4 && same && a.is_cell(c); ++i) {
      same = a.neighbor(c, i) == b.neighbor(c, i);
    }
  }
  CHECK(same);
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
    TriangulationOptions sequential;
    TriangulationOptions parallel;
    parallel.threads = threads;
    parallel.parallel_min_round = 100;
    const RegularTriangulation3 one = rstruct::test::build(in, sequential);
    const RegularTriangulation3 many = rstruct::test::build(in, parallel);
    const auto report = many.is_valid();
    RC_ASSERT(report.ok);
    RC_ASSERT(cell_set(many) == cell_set(one));
    RC_ASSERT(hidden_ids(many) == hidden_ids(one));
    RC_ASSERT(duplicate_pairs(many) == duplicate_pairs(one));
  });
}
