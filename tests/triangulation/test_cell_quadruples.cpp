// RegularTriangulation3::take_finite_cells: the finite cells' vertices compacted over the
// cell array, against a copy of them made before; RegularTriangulation3::delaunay_cells
// (the cells renamed to input ids while compacted) against the full construction.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <vector>

#include "generators.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"

namespace {

using rstruct::Point3;
using rstruct::triangulation::CellId;
using rstruct::triangulation::DelaunayCells;
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

using Quadruples = std::vector<std::array<VertexId, 4>>;

Quadruples sorted_each(std::span<const std::array<VertexId, 4>> cells) {
  Quadruples out(cells.begin(), cells.end());
  for (auto& q : out) std::sort(q.begin(), q.end());
  return out;
}

/// delaunay_cells(points, options) against constructing the triangulation with the same
/// options and taking its cells: the same quadruples (each sorted), in the same order when
/// the cell ids do not depend on timing (`same_order`), the same duplicates, the same
/// statistics of a sequential insertion.
void check_delaunay_cells(const std::vector<Point3>& points, const TriangulationOptions& options,
                          bool same_order) {
  RegularTriangulation3 full(points, options);
  const std::vector<rstruct::triangulation::DuplicatePoint> duplicates(
      full.duplicate_points().begin(), full.duplicate_points().end());
  const auto stats = full.stats();
  Quadruples expected = sorted_each(full.take_finite_cells(options.threads).quadruples());
  const DelaunayCells lean = RegularTriangulation3::delaunay_cells(points, options);
  Quadruples got(lean.cells.quadruples().begin(), lean.cells.quadruples().end());
  REQUIRE(got.size() == expected.size());
  for (const auto& q : got) CHECK(std::is_sorted(q.begin(), q.end()));
  if (!same_order) {
    std::sort(expected.begin(), expected.end());
    std::sort(got.begin(), got.end());
  }
  std::size_t wrong = 0;
  for (std::size_t k = 0; k < got.size(); ++k) wrong += got[k] != expected[k];
  CHECK(wrong == 0);
  REQUIRE(lean.duplicates.size() == duplicates.size());
  for (std::size_t k = 0; k < duplicates.size(); ++k) {
    CHECK(lean.duplicates[k].point == duplicates[k].point);
    CHECK(lean.duplicates[k].vertex == duplicates[k].vertex);
  }
  // Parallel passes count the work of abandoned attempts, which depends on timing.
  if (options.threads == 1) {
    CHECK(lean.stats.power_test_calls == stats.power_test_calls);
    CHECK(lean.stats.conflict_cells == stats.conflict_cells);
    CHECK(lean.stats.walk_steps == stats.walk_steps);
  } else {
    CHECK(lean.stats.threads == stats.threads);
    CHECK(lean.stats.lock_passes > 0);
  }
}

}  // namespace

TEST_CASE("delaunay_cells: the cells and reports of the full construction, each sorted") {
  using namespace rstruct::test;
  TriangulationOptions options;
  SECTION("uniform, one thread") { check_delaunay_cells(uniform_points(3000, 11), options, true); }
  SECTION("a grid (cospherical cells)") { check_delaunay_cells(grid_points(6, 5, 7), options, true); }
  SECTION("duplicates: reported in input ids") {
    check_delaunay_cells(with_duplicates(2000, 12, 300).points, options, true);
    check_delaunay_cells(duplicate_points(500, 40, 13), options, true);
  }
  SECTION("in input order (no renaming)") {
    options.spatial_sort = false;
    check_delaunay_cells(with_duplicates(1500, 14, 100).points, options, true);
  }
  SECTION("built on two threads with locks, as the pole analysis does") {
    // Torus points, exact copies of 50 of them, the 8 corners of a box inserted first.
    std::vector<Point3> points = torus_points(20000, 19);
    for (int i = 0; i < 50; ++i) points.push_back(points[static_cast<std::size_t>(97 * i)]);
    const Input corners = torus_with_box_corners();
    points.insert(points.end(), corners.points.end() - 8, corners.points.end());
    options.threads = 2;
    options.insert_first = 8;
    options.parallel_scheme = TriangulationOptions::ParallelScheme::locks;
    options.parallel_min_round = 2000;
    check_delaunay_cells(points, options, false);
  }
  SECTION("a canonical order: the full construction's cells") {
    options.threads = 2;
    options.parallel_scheme = TriangulationOptions::ParallelScheme::locks;
    options.canonical_order = true;
    options.parallel_min_round = 2000;
    check_delaunay_cells(torus_points(20000, 15), options, true);
  }
}

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
