// is_valid() after every insertion on random and degenerate inputs; zero weights give the
// Delaunay triangulation; the result does not depend on the insertion order.
#include <rapidcheck/catch.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <numeric>

#include "generators.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"

namespace {

using rstruct::Point3;
using rstruct::test::cell_set;
using rstruct::triangulation::RegularTriangulation3;
using rstruct::triangulation::TriangulationOptions;
using rstruct::triangulation::VertexId;

using rstruct::test::build;
using rstruct::test::Input;

Input degenerate_input(int kind, std::uint64_t seed, std::size_t n) {
  using namespace rstruct::test;
  switch (kind) {
    case 0: return {uniform_points(n, seed), {}};
    case 1: {
      const int s = 2 + static_cast<int>(seed % 4);  // grids 2^3 .. 5^3
      return {grid_points(s, s, s), {}};
    }
    case 2: return {sphere_points(static_cast<int>(seed % 3) == 0 ? 26 : 50), {}};
    case 3: return {few_plane_points(n, 2 + static_cast<int>(seed % 3), seed), {}};
    case 4: return {duplicate_points(n, 12, seed), {}};
    case 5: return {uniform_points(n, seed), hiding_weights(n, 0.3, seed ^ 5)};
    case 6: {
      std::vector<Point3> p = duplicate_points(n, 12, seed);
      return {p, hiding_weights(n, 2.0, seed ^ 6)};
    }
    default: {
      std::vector<Point3> p = grid_points(4, 4, 3);
      return {p, hiding_weights(p.size(), 1.5, seed ^ 7)};
    }
  }
}

}  // namespace

TEST_CASE("is_valid after every insertion") {
  rc::prop("random, grid, cospherical, few-plane, duplicate-heavy, hidden-heavy", [] {
    const int kind = *rc::gen::inRange(0, 8);
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    const auto n = static_cast<std::size_t>(*rc::gen::inRange(4, 80));
    RC_TAG(kind);
    const Input in = degenerate_input(kind, seed, n);
    TriangulationOptions options;
    options.seed = seed;
    std::size_t calls = 0;
    std::string failure;
    options.after_insertion = [&](const RegularTriangulation3& t, VertexId) {
      ++calls;
      if (failure.empty()) failure = t.is_valid().message;
    };
    try {
      const RegularTriangulation3 t = build(in, options);
      RC_ASSERT(failure == std::string());
      RC_ASSERT(calls == in.points.size());
      RC_ASSERT(t.number_of_vertices() + t.hidden_points().size() +
                    t.duplicate_points().size() ==
                in.points.size());
      if (in.weights.empty()) RC_ASSERT(t.hidden_points().empty());
    } catch (const rstruct::InvalidInput&) {
      RC_ASSERT(kind == 3 || kind == 4 || kind == 6);  // may be flat by chance
    }
  });
}

TEST_CASE("10^3 grid, cospherical sets and duplicates end valid") {
  const RegularTriangulation3 grid(rstruct::test::grid_points(10, 10, 10));
  CHECK(grid.is_valid().message == "");
  CHECK(grid.number_of_vertices() == 1000);
  // Every unit cube of the grid is split into tetrahedra of volume 1/6 in total.
  CHECK(grid.number_of_finite_cells() >= 729 * 5);
  const RegularTriangulation3 sphere(rstruct::test::sphere_points(101));
  CHECK(sphere.is_valid().message == "");
  CHECK(sphere.number_of_vertices() == sphere.number_of_points());
  std::vector<Point3> twice = rstruct::test::grid_points(3, 3, 3);
  twice.insert(twice.end(), twice.begin(), twice.end());
  const RegularTriangulation3 dup(twice);
  CHECK(dup.is_valid().message == "");
  CHECK(dup.number_of_vertices() == 27);
  REQUIRE(dup.duplicate_points().size() == 27);
  for (const auto& d : dup.duplicate_points()) {
    CHECK(d.point == d.vertex + 27);  // the smaller id wins at equal weight
  }
}

TEST_CASE("the filter's failures are counted: many on a grid, few on random points") {
  // A grid's cospherical cells give insphere determinants of exactly zero, which no
  // floating-point filter decides; random points almost never come that close.
  const RegularTriangulation3 grid(rstruct::test::grid_points(10, 10, 10));
  const auto& g = grid.stats();
  INFO("grid: " << g.filter_misses << " of " << g.power_test_calls);
  CHECK(g.filter_misses > g.power_test_calls / 10);
  CHECK(g.filter_misses <= g.power_test_calls);
  const RegularTriangulation3 random(rstruct::test::uniform_points(5000, 3));
  const auto& r = random.stats();
  INFO("random: " << r.filter_misses << " of " << r.power_test_calls);
  CHECK(r.power_test_calls > 5000);
  CHECK(r.filter_misses < r.power_test_calls / 1000);
}

TEST_CASE("each walk starts next to its point: about one step per point on random points") {
  // The walk starts in the previous star's cell with the centroid nearest to the point
  // (Builder::nearest_star_cell); from an arbitrary cell of that star it took about 5.6
  // steps per point, from the nearest about 1.1.
  const std::size_t n = 20000;
  const RegularTriangulation3 plain(rstruct::test::uniform_points(n, 11));
  INFO("Delaunay: " << plain.stats().walk_steps << " steps");
  CHECK(plain.stats().walk_steps < 2 * n);
  // Weights up to (0.8 x mean spacing)^2, as in bench_triangulation: a few percent hidden.
  const double spacing = std::cbrt(1.0 / static_cast<double>(n));
  const RegularTriangulation3 weighted(
      rstruct::test::uniform_points(n, 12),
      rstruct::test::hiding_weights(n, 0.64 * spacing * spacing, 13));
  INFO("hidden: " << weighted.hidden_points().size());
  CHECK(weighted.hidden_points().size() > n / 200);
  INFO("weighted: " << weighted.stats().walk_steps << " steps");
  CHECK(weighted.stats().walk_steps < 2 * n);
}

TEST_CASE("the points and weights come back in input order") {
  // The construction stores the points in insertion order and permutes them back at the
  // end, several segments of the permutation's cycles at a time
  // (Builder::permute_points_to_input_order; segment starts every n/64 ranks, at most
  // 1,024 apart, so 70,000 points take the widest spacing).
  for (const std::size_t n : {std::size_t{5}, std::size_t{97}, std::size_t{3000},
                              std::size_t{70000}}) {
    INFO("n = " << n);
    const std::vector<Point3> points = rstruct::test::uniform_points(n, 21 + n);
    const std::vector<double> weights = rstruct::test::hiding_weights(n, 1e-4, 22 + n);
    const RegularTriangulation3 plain(points);
    const RegularTriangulation3 weighted(points, weights);
    std::size_t wrong_points = 0;
    std::size_t wrong_weights = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const auto v = static_cast<VertexId>(i);
      wrong_points += plain.point(v) == points[i] ? 0 : 1;
      wrong_points += weighted.point(v) == points[i] ? 0 : 1;
      wrong_weights += weighted.weight(v) == weights[i] ? 0 : 1;
    }
    CHECK(wrong_points == 0);
    CHECK(wrong_weights == 0);
    if (n <= 3000) {
      CHECK(plain.is_valid());
      CHECK(weighted.is_valid());
    }
  }
}

TEST_CASE("duplicates: the larger weight wins") {
  std::vector<Point3> p = rstruct::test::grid_points(2, 2, 2);
  p.push_back(p[3]);
  std::vector<double> w(9, 0.0);
  w[8] = 0.125;  // the later copy is heavier
  const RegularTriangulation3 t(p, w);
  CHECK(t.is_valid().message == "");
  CHECK(!t.is_vertex(3));
  CHECK(t.is_vertex(8));
  REQUIRE(t.duplicate_points().size() == 1);
  CHECK(t.duplicate_points()[0].point == 3);
  CHECK(t.duplicate_points()[0].vertex == 8);
}

TEST_CASE("zero weights give exactly the Delaunay triangulation") {
  rc::prop("weighted with zeros == unweighted", [] {
    const int kind = *rc::gen::inRange(0, 5);
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    const auto n = static_cast<std::size_t>(*rc::gen::inRange(4, 200));
    Input in = degenerate_input(kind, seed, n);
    try {
      const RegularTriangulation3 d(in.points);
      const RegularTriangulation3 r(in.points, std::vector<double>(in.points.size(), 0.0));
      RC_ASSERT(cell_set(d) == cell_set(r));
      RC_ASSERT(d.duplicate_points().size() == r.duplicate_points().size());
      RC_ASSERT(r.hidden_points().empty());
    } catch (const rstruct::InvalidInput&) {
      RC_ASSERT(kind == 3 || kind == 4);
    }
  });
}

TEST_CASE("the result does not depend on the insertion order") {
  rc::prop("BRIO seeds and input order give the same cells", [] {
    const int kind = *rc::gen::inRange(0, 8);
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    const auto n = static_cast<std::size_t>(*rc::gen::inRange(4, 300));
    const Input in = degenerate_input(kind, seed, n);
    TriangulationOptions a;
    a.seed = seed;
    TriangulationOptions b;
    b.seed = seed * 31 + 7;
    TriangulationOptions c;
    c.spatial_sort = false;
    try {
      const RegularTriangulation3 ta = build(in, a);
      const RegularTriangulation3 tb = build(in, b);
      const RegularTriangulation3 tc = build(in, c);
      RC_ASSERT(cell_set(ta) == cell_set(tb));
      RC_ASSERT(cell_set(ta) == cell_set(tc));
      RC_ASSERT(ta.hidden_points().size() == tc.hidden_points().size());
      RC_ASSERT(ta.duplicate_points().size() == tc.duplicate_points().size());
    } catch (const rstruct::InvalidInput&) {
      RC_ASSERT(kind == 3 || kind == 4 || kind == 6);
    }
  });
  rc::prop("relabelling generic points relabels the cells", [] {
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    const auto n = static_cast<std::size_t>(*rc::gen::inRange(5, 300));
    const std::vector<Point3> p = rstruct::test::uniform_points(n, seed);
    std::vector<std::uint32_t> perm(n);
    std::iota(perm.begin(), perm.end(), 0u);
    rstruct::test::Random r(seed ^ 0xABCDEF);
    for (std::size_t i = n; i > 1; --i) std::swap(perm[i - 1], perm[r.next() % i]);
    std::vector<Point3> q(n);
    for (std::size_t i = 0; i < n; ++i) q[perm[i]] = p[i];
    auto expected = cell_set(RegularTriangulation3(p));
    std::set<rstruct::test::CellKey> mapped;
    for (auto k : expected) {
      for (auto& v : k) v = perm[v];
      std::sort(k.begin(), k.end());
      mapped.insert(k);
    }
    RC_ASSERT(cell_set(RegularTriangulation3(q)) == mapped);
  });
}

TEST_CASE("the BRIO divisor changes the insertion order, not the triangulation") {
  // Large enough for several rounds (the first holds at most 256 expected points).
  const std::size_t n = 6000;
  for (const bool weighted : {false, true}) {
    const Input in{rstruct::test::uniform_points(n, 17),
                   weighted ? rstruct::test::hiding_weights(n, 0.3, 18) : std::vector<double>{}};
    TriangulationOptions reference;
    const RegularTriangulation3 t4 = build(in, reference);
    REQUIRE(reference.brio_divisor == 4);
    std::uint64_t walk_of_2 = 0;
    for (const std::uint32_t divisor : {2u, 0u, 16u, 1000u}) {
      TriangulationOptions options;
      options.brio_divisor = divisor;
      const RegularTriangulation3 t = build(in, options);
      CHECK(t.is_valid());
      CHECK(cell_set(t) == cell_set(t4));
      CHECK(t.hidden_points().size() == t4.hidden_points().size());
      // Another order: the walks differ. 0 acts as 2: the same order.
      CHECK(t.stats().walk_steps != t4.stats().walk_steps);
      if (divisor == 2) walk_of_2 = t.stats().walk_steps;
      if (divisor == 0) CHECK(t.stats().walk_steps == walk_of_2);
    }
  }
}

TEST_CASE("a weighted cavity with hundreds of boundary vertices hides the vertices inside") {
  // 300 weightless points on the unit sphere, 40 weightless points within 0.3 of its
  // centre, then the centre with weight 0.36: its cavity is bounded by the sphere points
  // (more than the boundary numbering holds, so the hidden vertices are found by the
  // general method), and it hides every inner point (an inner point x's power cell would
  // need y·x ≥ (|x|² + 0.36) / 2 beyond the sphere points' bisectors).
  std::vector<Point3> p;
  std::vector<double> w;
  rstruct::test::Random r(7);
  while (p.size() < 340) {
    const Point3 q{r.uniform() * 2 - 1, r.uniform() * 2 - 1, r.uniform() * 2 - 1};
    const double len = norm(q);
    if (len < 0.1 || len > 1) continue;
    p.push_back(p.size() < 300 ? q / len : q * (0.3 / len) * r.uniform());
    w.push_back(0);
  }
  p.push_back({0, 0, 0});
  w.push_back(0.36);
  TriangulationOptions sequential;
  sequential.spatial_sort = false;
  for (const auto& options : {sequential, TriangulationOptions{}}) {
    const RegularTriangulation3 t(p, w, options);
    CHECK(t.is_valid().message == "");
    CHECK(t.hidden_points().size() == 40);
    CHECK(t.number_of_vertices() == 301);
    if (!options.spatial_sort) CHECK(t.stats().large_cavities >= 1);
  }
}

TEST_CASE("a cavity with hundreds of boundary vertices (the star is linked by hashing)") {
  // Points near a sphere, then its centre: every cell's circumsphere holds the centre, so
  // the last insertion's cavity is the whole triangulation.
  std::vector<Point3> p;
  rstruct::test::Random r(99);
  while (p.size() < 300) {
    const Point3 q{r.uniform() * 2 - 1, r.uniform() * 2 - 1, r.uniform() * 2 - 1};
    const double len = norm(q);
    if (len > 0.1) p.push_back(q / len);
  }
  p.push_back({0, 0, 0});
  TriangulationOptions sequential;
  sequential.spatial_sort = false;
  for (const auto& options : {sequential, TriangulationOptions{}}) {
    const RegularTriangulation3 t(p, options);
    CHECK(t.is_valid().message == "");
    CHECK(t.number_of_vertices() == p.size());
    if (!options.spatial_sort) CHECK(t.stats().large_cavities >= 1);
  }
}
