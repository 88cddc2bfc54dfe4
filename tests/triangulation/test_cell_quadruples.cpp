// RegularTriangulation3::take_finite_cells: the finite cells' vertices compacted over the
// cell array, against a copy of them made before.
#include <catch2/catch.hpp>

#include <array>
#include <vector>

#include "generators.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"

namespace {

using rstruct::triangulation::CellId;
using rstruct::triangulation::kInfiniteVertex;
using rstruct::triangulation::RegularTriangulation3;
using rstruct::triangulation::TriangulationOptions;
using rstruct::triangulation::VertexId;

/// The finite cells' vertices in increasing id, read through the public interface.
std::vector<std::array<VertexId, 4>> finite_cells(const RegularTriangulation3& t) {
  std::vector<std::array<VertexId, 4>> cells;
  for (std::size_t c = 0; c < t.cell_capacity(); ++c) {
    const auto id = static_cast<CellId>(c);
    if (!t.is_cell(id) || t.is_infinite(id)) continue;
    cells.push_back(t.vertices(id));
  }
  return cells;
}

void check_take(RegularTriangulation3 t, unsigned threads) {
  const std::vector<std::array<VertexId, 4>> expected = finite_cells(t);
  const std::size_t points = t.number_of_points();
  const std::size_t hidden = t.hidden_points().size();
  // Free cells among the live ones (hidden points, parallel regions) make the compaction
  // move cells by different amounts.
  INFO("capacity " << t.cell_capacity() << ", finite " << expected.size());
  REQUIRE(t.number_of_finite_cells() == expected.size());
  const rstruct::triangulation::CellQuadruples q = t.take_finite_cells(threads);
  REQUIRE(q.size() == expected.size());
  std::size_t wrong = 0;
  for (std::size_t k = 0; k < q.size(); ++k) wrong += q.quadruples()[k] != expected[k];
  CHECK(wrong == 0);
  CHECK(t.number_of_cells() == 0);
  CHECK(t.cell_capacity() == 0);
  CHECK(t.number_of_points() == points);
  CHECK(t.hidden_points().size() == hidden);
}

}  // namespace

TEST_CASE("take_finite_cells: the finite cells in id order, whatever the threads") {
  using namespace rstruct::test;
  SECTION("small") { check_take(RegularTriangulation3(uniform_points(30, 1)), 2); }
  SECTION("a grid (cospherical cells)") { check_take(RegularTriangulation3(grid_points(5, 4, 6)), 2); }
  // 60,000 points: about 400,000 cells, 7 chunks of 65,536 ids, compacted in 4 waves.
  SECTION("many chunks, one thread") {
    check_take(RegularTriangulation3(uniform_points(60000, 2)), 1);
  }
  SECTION("many chunks, three threads") {
    check_take(RegularTriangulation3(uniform_points(60000, 3)), 3);
  }
  SECTION("weighted, hidden points leave free cells") {
    check_take(RegularTriangulation3(uniform_points(60000, 4), hiding_weights(60000, 0.3, 4)), 2);
  }
  SECTION("built on two threads (free cells between the workers' regions)") {
    TriangulationOptions options;
    options.threads = 2;
    check_take(RegularTriangulation3(torus_points(60000, 5), options), 2);
  }
}

TEST_CASE("take_finite_cells: the quadruples outlive the triangulation, and move") {
  using namespace rstruct::test;
  rstruct::triangulation::CellQuadruples moved;
  std::vector<std::array<VertexId, 4>> expected;
  {
    RegularTriangulation3 t(uniform_points(2000, 6));
    expected = finite_cells(t);
    rstruct::triangulation::CellQuadruples q = t.take_finite_cells();
    moved = std::move(q);
    CHECK(q.size() == 0);  // NOLINT(bugprone-use-after-move): moved-from is empty
  }
  REQUIRE(moved.size() == expected.size());
  CHECK(std::vector<std::array<VertexId, 4>>(moved.quadruples().begin(), moved.quadruples().end()) ==
        expected);
  std::size_t infinite = 0;
  for (const auto& cell : moved.quadruples()) {
    for (const VertexId v : cell) infinite += v == kInfiniteVertex ? 1 : 0;
  }
  CHECK(infinite == 0);
}
