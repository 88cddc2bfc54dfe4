#include "rstruct/complex/dual_complex.hpp"

#include <rapidcheck/catch.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "complex/rational_geometry.hpp"
#include "rstruct/complex/homology.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"

using namespace rstruct;
using namespace rstruct::complex;
using testing::BallSet;
using testing::triangulate;

namespace {

/// Every simplex of R classified as the brute force says; facet classes consistent.
void check_against_brute_force(const BallSet& set, const DualComplex& k) {
  const auto& r = k.triangulation;
  const auto expect = [&](int d, SimplexIndex i, std::vector<VertexId> sigma) {
    RC_ASSERT(k.in_k[d][i] == testing::brute_force_in_k(set.exact, sigma));
  };
  for (SimplexIndex i = 0; i < r.size(0); ++i) expect(0, i, {r.vertices()[i]});
  for (SimplexIndex i = 0; i < r.size(1); ++i) {
    expect(1, i, {r.edges()[i].begin(), r.edges()[i].end()});
  }
  for (SimplexIndex i = 0; i < r.size(2); ++i) {
    expect(2, i, {r.triangles()[i].begin(), r.triangles()[i].end()});
  }
  for (SimplexIndex i = 0; i < r.size(3); ++i) {
    expect(3, i, {r.tetrahedra()[i].begin(), r.tetrahedra()[i].end()});
  }
  RC_ASSERT(k.complex().is_valid());
}

BallSet ring_of_balls(int n, double radius, double ring_radius) {
  BallSet set;
  const double pi = std::acos(-1.0);
  for (int i = 0; i < n; ++i) {
    const double a = 2 * pi * i / n;
    // Alternate heights so that no four centres are coplanar.
    set.points.push_back({{ring_radius * std::cos(a), ring_radius * std::sin(a),
                           (i % 2 ? 0.05 : -0.05) * (1 + 0.1 * i)},
                          radius * radius});
  }
  return set;
}

}  // namespace

TEST_CASE("a ring of overlapping balls has a dual complex with one loop") {
  // Neighbours at distance 2·sin(π/8)·4 ≈ 3.06 overlap for radius 1.7; opposite ones
  // (distance 8) do not, and no three balls share a point near the centre.
  auto set = ring_of_balls(8, 1.7, 4.0);
  REQUIRE(triangulate(set));
  const auto k = dual_complex(set.points, set.cells);
  CHECK(betti_numbers(k.complex()) == BettiNumbers{{1, 1, 0, 0}});
  CHECK(k.counts()[0] == 8);
  CHECK(k.counts()[3] == 0);
  // Shrunk balls fall apart into 8 points; grown balls fill the ring's hole.
  for (auto& p : set.points) p.w = 1.0;
  CHECK(betti_numbers(dual_complex(set.points, set.cells).complex()) ==
        BettiNumbers{{8, 0, 0, 0}});
  for (auto& p : set.points) p.w = 25.0;
  CHECK(betti_numbers(dual_complex(set.points, set.cells).complex()) ==
        BettiNumbers{{1, 0, 0, 0}});
}

TEST_CASE("four balls with a common point give a tetrahedron; facet classes") {
  BallSet set;
  // Circumcentre near (1, 1, 1), at distance about sqrt(3) < 2 from each centre.
  set.points = {{{0, 0, 0}, 4.0}, {{2, 0.1, 0}, 4.0}, {{0.2, 2, 0.1}, 4.0}, {{0.1, 0.3, 2}, 4.0},
                {{10, 10, 10}, 1.0}};
  REQUIRE(triangulate(set));
  const auto k = dual_complex(set.points, set.cells);
  REQUIRE(k.counts()[3] == 1);
  // The lone far ball is an isolated vertex of K.
  CHECK(betti_numbers(k.complex()) == BettiNumbers{{2, 0, 0, 0}});
  const auto classes = k.facet_class_counts();
  CHECK(classes[static_cast<int>(FacetClass::regular)] == 4);
  CHECK(classes[static_cast<int>(FacetClass::interior)] == 0);
  CHECK(classes[static_cast<int>(FacetClass::singular)] == 0);
  CHECK(classes[static_cast<int>(FacetClass::exterior)] + 4 == k.triangulation.size(2));
}

TEST_CASE("a ball inside another ball that still has a power cell is not in K") {
  // Ball B (centre 9, radius 0.5) lies inside A (centre 0, radius 10); B's power cell is
  // x > 10.04, where B's power is positive: B is a vertex of R but not of K.
  BallSet set;
  set.points = {{{0, 0, 0}, 100.0}, {{9, 0.01, 0.02}, 0.25}, {{-30, 1, 0}, 1.0},
                {{0, -30, 1}, 1.0}, {{1, 0, -30}, 1.0}};
  REQUIRE(triangulate(set));
  const auto k = dual_complex(set.points, set.cells);
  REQUIRE(k.triangulation.find_vertex(1).has_value());
  CHECK_FALSE(k.in_k[0][*k.triangulation.find_vertex(1)]);
  check_against_brute_force(set, k);
}

TEST_CASE("cells naming missing points are rejected") {
  const std::vector<WeightedPoint> pts = {{{0, 0, 0}, 1.0}, {{1, 0, 0}, 1.0}, {{0, 1, 0}, 1.0}};
  const std::vector<Tetrahedron> cells = {{0, 1, 2, 3}};
  CHECK_THROWS_AS(dual_complex(pts, cells), InvalidInput);
}

TEST_CASE("dual complex agrees with the brute-force definition on random ball sets") {
  for (const int lo : {1, 500}) {
    rc::prop(lo == 1 ? "random balls in general position" : "large overlapping balls", [lo] {
      BallSet set = testing::random_ball_set(lo);
      RC_PRE(triangulate(set));
      const auto k = dual_complex(set.points, set.cells);
      check_against_brute_force(set, k);
      // The facet classes count incident tetrahedra of K.
      const auto classes = k.facet_class_counts();
      RC_ASSERT(classes[0] + classes[1] + classes[2] + classes[3] == k.triangulation.size(2));
      RC_ASSERT(classes[1] + classes[2] + classes[3] == k.counts()[2]);
      const auto counts = k.counts();
      RC_CLASSIFY(counts[3] > 0 && counts[3] < k.triangulation.size(3), "some tetrahedra in K");
      RC_CLASSIFY(classes[1] > 0, "singular facets");
      RC_CLASSIFY(counts[0] < k.triangulation.size(0), "a vertex of R not in K");
      RC_CLASSIFY(counts[1] < k.triangulation.size(1), "an edge of R not in K");
    });
  }
}

namespace {

/// R from the real triangulation (exact, perturbed); no general-position requirement.
DualComplex dual_complex_via_triangulation(BallSet& set) {
  std::vector<Point3> centres;
  std::vector<double> weights;
  for (const auto& p : set.points) {
    centres.push_back(p.c);
    weights.push_back(p.w);
  }
  const triangulation::RegularTriangulation3 r(centres, weights);
  set.exact.clear();
  for (const auto& p : set.points) set.exact.push_back(testing::to_q(p));
  return dual_complex(r);
}

}  // namespace

TEST_CASE("dual complex on the regular triangulation agrees with brute force") {
  rc::prop("general position", [] {
    const int n = *rc::gen::inRange(3, 7);
    BallSet set;
    for (int i = 0; i < n; ++i) {
      const auto coord = [] { return *rc::gen::inRange(-1000000, 1000000) / 400000.0; };
      const double r = *rc::gen::inRange(100, 1000) / 600.0;
      set.points.push_back({{coord(), coord(), coord()}, r * r});
    }
    // Four small far balls so that the centres always span R³.
    set.points.push_back({{-3.1, -2.9, -3.3}, 0.25});
    set.points.push_back({{3.2, -3.05, -2.7}, 0.25});
    set.points.push_back({{-2.8, 3.3, -3.1}, 0.25});
    set.points.push_back({{-3.3, -3.2, 2.9}, 0.25});
    const auto k = dual_complex_via_triangulation(set);
    check_against_brute_force(set, k);
  });
  rc::prop("degenerate: integer grid points, equal or integer weights, duplicates", [] {
    // Points of the 3 × 3 × 3 grid (cospherical and coplanar subsets everywhere), some
    // repeated, with weights from {0, 1, 2, 4} (touching and nested balls).
    const int n = *rc::gen::inRange(4, 9);
    const bool equal = *rc::gen::arbitrary<bool>();
    BallSet set;
    for (int i = 0; i < n; ++i) {
      const double x = *rc::gen::inRange(0, 3);
      const double y = *rc::gen::inRange(0, 3);
      const double z = *rc::gen::inRange(0, 3);
      const double w = equal ? 1.0 : static_cast<double>(*rc::gen::elementOf(std::vector<int>{0, 1, 2, 4}));
      set.points.push_back({{x, y, z}, w});
    }
    set.points.push_back({{0, 0, 0}, 1.0});
    set.points.push_back({{2, 0, 0}, 1.0});
    set.points.push_back({{0, 2, 0}, 1.0});
    set.points.push_back({{0, 0, 2}, 1.0});  // never all coplanar
    const auto k = dual_complex_via_triangulation(set);
    check_against_brute_force(set, k);
  });
}
