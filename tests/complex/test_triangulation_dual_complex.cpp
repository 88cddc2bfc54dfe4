// classify_dual_complex (on the regular triangulation) against dual_complex (on the
// SimplicialComplex copy of it, checked against a brute force in test_dual_complex): the
// same K, simplex by simplex, and the same facet classes, on random ball sets, integer
// grids with equal weights, exactly cospherical points, zero weights and hidden balls, with
// one and with several threads.

#include "rstruct/complex/triangulation_dual_complex.hpp"

#include <rapidcheck/catch.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <utility>
#include <vector>

#include "rstruct/complex/dual_complex.hpp"
#include "rstruct/core/error.hpp"
#include "support/degenerate.hpp"

using namespace rstruct;
using namespace rstruct::complex;
using rstruct::triangulation::RegularTriangulation3;
using rstruct::triangulation::VertexStars;

namespace {

/// Both classifications of the regular triangulation of the balls agree.
void check_same(const std::vector<Point3>& centres, const std::vector<double>& weights) {
  const RegularTriangulation3 rt(centres, weights);
  const DualComplex reference = dual_complex(rt);
  const SimplicialComplex expected = reference.complex();
  const VertexStars built(rt, 1);
  // Neighbour lists built by the stars, or deferred to the edge pass (which must then
  // install the same lists), each with one and with several threads.
  for (const auto& [threads, neighbors] :
       {std::pair{1u, VertexStars::Neighbors::build}, std::pair{3u, VertexStars::Neighbors::build},
        std::pair{1u, VertexStars::Neighbors::deferred},
        std::pair{3u, VertexStars::Neighbors::deferred}}) {
    VertexStars stars(rt, threads, VertexStars::kCellsPerThread, neighbors);
    const TriangulationDualComplex k = classify_dual_complex(rt, stars, threads);
    RC_ASSERT(stars.has_neighbors());
    for (triangulation::VertexId v = 0; v < centres.size(); ++v) {
      const auto mine = stars.neighbors(v);
      const auto expected = built.neighbors(v);
      RC_ASSERT(std::equal(mine.begin(), mine.end(), expected.begin(), expected.end()));
    }
    RC_ASSERT(k.complex.is_valid());
    RC_ASSERT(k.complex.vertices() == expected.vertices());
    RC_ASSERT(k.complex.edges() == expected.edges());
    RC_ASSERT(k.complex.triangles() == expected.triangles());
    RC_ASSERT(k.complex.tetrahedra() == expected.tetrahedra());
    RC_ASSERT(k.facet_classes == reference.facet_class_counts());
    for (int d = 0; d < 4; ++d) {
      RC_ASSERT(k.triangulation_counts[static_cast<std::size_t>(d)] ==
                reference.triangulation.size(d));
    }
  }
}

/// Random weights r² with r in [0, scale) (integers / 64: exact, often equal).
std::vector<double> random_weights(std::size_t n, int scale) {
  std::vector<double> w;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = *rc::gen::inRange(0, 64 * scale) / 64.0;
    w.push_back(r * r);
  }
  return w;
}

}  // namespace

TEST_CASE("vertex stars list each vertex's cells and neighbours") {
  const std::vector<Point3> grid = testing::integer_grid(4);
  const RegularTriangulation3 rt(grid);
  // One thread, and three filling the stars of a range of vertices each (on this small
  // triangulation only when told to split from one cell per thread on).
  const unsigned threads = GENERATE(1u, 3u);
  const VertexStars stars(rt, threads, 1);
  std::size_t edge_ends = 0;
  for (triangulation::VertexId v = 0; v < grid.size(); ++v) {
    auto expected = rt.incident_cells(v);
    std::sort(expected.begin(), expected.end());
    const auto cells = stars.cells(v);
    CHECK(std::vector<triangulation::CellId>(cells.begin(), cells.end()) == expected);
    const auto adjacent = rt.adjacent_vertices(v);
    std::vector<triangulation::VertexId> sorted(adjacent.begin(), adjacent.end());
    std::sort(sorted.begin(), sorted.end());
    const auto neighbors = stars.neighbors(v);
    CHECK(std::vector<triangulation::VertexId>(neighbors.begin(), neighbors.end()) == sorted);
    edge_ends += neighbors.size();
  }
  CHECK(stars.number_of_finite_edges() * 2 == edge_ends);
}

TEST_CASE("dual complex on the triangulation equals the dual complex of its cells") {
  rc::prop("random balls", [] {
    const int n = *rc::gen::inRange(5, 40);
    const int scale = *rc::gen::inRange(1, 4);
    std::vector<Point3> centres;
    for (int i = 0; i < n; ++i) {
      const auto coord = [] { return *rc::gen::inRange(-1000, 1000) / 256.0; };
      centres.push_back({coord(), coord(), coord()});
    }
    RC_PRE(centres.size() >= 4u);
    std::vector<double> weights = random_weights(centres.size(), scale);
    try {
      check_same(centres, weights);
    } catch (const InvalidInput&) {
      RC_DISCARD("flat point set");
    }
  });
  rc::prop("integer grid, equal or random weights (ties everywhere)", [] {
    const int n = *rc::gen::inRange(2, 5);
    const std::vector<Point3> grid = testing::integer_grid(n);
    const bool equal = *rc::gen::arbitrary<bool>();
    std::vector<double> weights =
        equal ? std::vector<double>(grid.size(), *rc::gen::inRange(0, 5) / 4.0)
              : random_weights(grid.size(), 2);
    check_same(grid, weights);
  });
}

TEST_CASE("degenerate ball sets: cospherical centres, touching and hidden balls") {
  // 4225 = 65²: many integer points on one sphere; equal weights make every orthosphere
  // the same sphere.
  const std::vector<Point3> sphere = testing::integer_sphere_points(4225);
  for (const double w : {0.0, 100.0, 1000.0, 4000.0}) {
    check_same(sphere, std::vector<double>(sphere.size(), w));
  }
  // Unit grid, radius 1/2: neighbouring balls touch in one point (a tie K decides as "in").
  const std::vector<Point3> grid = testing::integer_grid(4);
  check_same(grid, std::vector<double>(grid.size(), 0.25));
  // Radius sqrt(2)/2: balls on a square's diagonal touch; sqrt(3)/2: cube diagonals.
  check_same(grid, std::vector<double>(grid.size(), 0.5));
  check_same(grid, std::vector<double>(grid.size(), 0.75));
  // Hidden balls: small balls next to big ones.
  std::vector<double> mixed(grid.size(), 1.0);
  for (std::size_t i = 0; i < mixed.size(); i += 3) mixed[i] = 0.0;
  mixed[5] = 9.0;
  check_same(grid, mixed);
}
