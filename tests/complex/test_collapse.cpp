#include "rstruct/complex/collapse.hpp"

#include <rapidcheck/catch.h>

#include <catch2/catch.hpp>

#include "complex/complex_test_support.hpp"
#include "complex/known_complexes.hpp"
#include "rstruct/complex/coface_index.hpp"
#include "rstruct/complex/homology.hpp"
#include "rstruct/complex/manifold.hpp"

using namespace rstruct::complex;

namespace {

/// No simplex of k is a proper face of exactly one simplex (checked from scratch).
bool has_no_free_face(const SimplicialComplex& k) {
  const CofaceIndex cof(k);
  for (int d = 0; d < 3; ++d) {
    for (SimplexIndex i = 0; i < k.size(d); ++i) {
      if (cof.degree(d, i) != 1) continue;
      const SimplexIndex tau = cof.cofaces(d, i)[0];
      if (d == 2 || cof.degree(d + 1, tau) == 0) return false;
    }
  }
  return true;
}

SimplicialComplex relabel_randomly(const SimplicialComplex& k) {
  const auto ids = *testing::random_injective_ids(k.size(0));
  return SimplicialComplex::closure_of(
      testing::relabelled(k, [&](VertexId v) { return ids[k.find_vertex(v).value()]; }));
}

}  // namespace

TEST_CASE("a triangulated ball collapses to a point") {
  const auto ball = SimplicialComplex::closure_of(testing::subdivided_box(3, 2, 2));
  const auto result = collapse_free_faces(ball);
  CHECK(result.complex.size(0) == 1);
  CHECK(result.complex.total_size() == 1);
  CHECK(result.collapses * 2 + 1 == ball.total_size());
  CHECK(result.removed[3] == ball.size(3));
  CHECK(result.complex.is_valid());
}

TEST_CASE("closed surfaces have no free face") {
  for (const auto& triangles : {testing::torus7(), testing::klein_bottle(), testing::octahedron()}) {
    const auto k = SimplicialComplex::closure_of(triangles);
    const auto result = collapse_free_faces(k);
    CHECK(result.collapses == 0);
    CHECK(result.complex.triangles() == k.triangles());
  }
}

TEST_CASE("a thickened surface with fins collapses to the surface's homotopy type") {
  // Sphere with a solid tetrahedron glued on one face, a dangling triangle and an edge.
  SimplexLists lists;
  lists.triangles = testing::octahedron();
  lists.tetrahedra = {{0, 2, 4, 10}};
  lists.triangles.push_back({1, 3, 11});
  lists.edges = {{5, 12}, {12, 13}};
  const auto k = SimplicialComplex::closure_of(lists);
  const auto result = collapse_free_faces(k);
  // The tetrahedron goes through its lowest free face (0, 2, 4), which was a sphere
  // triangle: the sphere gets a bump made of the other three faces.
  CHECK(result.complex.size(2) == 10);
  CHECK_FALSE(result.complex.find(Triangle{0, 2, 4}).has_value());
  CHECK(result.complex.find(Triangle{2, 4, 10}).has_value());
  CHECK(result.complex.size(0) == 7);
  CHECK(is_closed_2_manifold(result.complex));
  CHECK(betti_numbers(result.complex) == betti_numbers(k));
  // Depth-first takes the newest free face first, (2, 4, 10): the bump goes away and
  // exactly the octahedron is left.
  const auto depth = collapse_free_faces(k, CollapseOrder::depth_first);
  CHECK(depth.complex.triangles() ==
        SimplicialComplex::closure_of(testing::octahedron()).triangles());
}

TEST_CASE("a solid torus collapses to a circle") {
  // Triangular prism ring: three triangles (0,1,2)+3i glued cyclically, each prism split
  // into three tetrahedra.
  std::vector<Tetrahedron> tets;
  for (VertexId i = 0; i < 4; ++i) {
    const VertexId a = 3 * i, b = 3 * i + 1, c = 3 * i + 2;
    const VertexId j = (i + 1) % 4;
    const VertexId d = 3 * j, e = 3 * j + 1, f = 3 * j + 2;
    tets.push_back({a, b, c, d});
    tets.push_back({b, c, d, e});
    tets.push_back({c, d, e, f});
  }
  const auto k = SimplicialComplex::closure_of(tets);
  REQUIRE(betti_numbers(k) == BettiNumbers{{1, 1, 0, 0}});
  const auto result = collapse_free_faces(k);
  CHECK(betti_numbers(result.complex) == BettiNumbers{{1, 1, 0, 0}});
  CHECK(result.complex.size(3) == 0);
  CHECK(has_no_free_face(result.complex));
}

TEST_CASE("collapse keeps homology and leaves no free face") {
  rc::prop("random complexes, both orders", [] {
    const auto k = SimplicialComplex::closure_of(*testing::random_simplex_lists(9, 40));
    const auto order = *rc::gen::element(CollapseOrder::breadth_first, CollapseOrder::depth_first);
    const auto result = collapse_free_faces(k, order);
    RC_ASSERT(result.complex.is_valid());
    RC_ASSERT(has_no_free_face(result.complex));
    RC_ASSERT(betti_numbers(result.complex) == betti_numbers(k));
    RC_ASSERT(testing::dense_betti(result.complex) == testing::dense_betti(k));
    RC_ASSERT(result.complex.total_size() + 2 * result.collapses == k.total_size());
  });
}

TEST_CASE("collapse result does not depend on the order of input lists") {
  rc::prop("the same complex built twice collapses identically", [] {
    const auto lists = *testing::random_simplex_lists(8, 30);
    auto shuffled = lists;
    std::reverse(shuffled.triangles.begin(), shuffled.triangles.end());
    std::reverse(shuffled.tetrahedra.begin(), shuffled.tetrahedra.end());
    const auto a = collapse_free_faces(SimplicialComplex::closure_of(lists)).complex;
    const auto b = collapse_free_faces(SimplicialComplex::closure_of(shuffled)).complex;
    RC_ASSERT(a.vertices() == b.vertices());
    RC_ASSERT(a.edges() == b.edges());
    RC_ASSERT(a.triangles() == b.triangles());
  });
}

TEST_CASE("relabelled triangulated balls collapse to a point") {
  rc::prop("Kuhn-subdivided boxes up to 3x3x3 under random labels, breadth-first", [] {
    const int nx = *rc::gen::inRange(1, 4);
    const int ny = *rc::gen::inRange(1, 4);
    const int nz = *rc::gen::inRange(1, 4);
    const auto ball = relabel_randomly(SimplicialComplex::closure_of(testing::subdivided_box(nx, ny, nz)));
    const auto result = collapse_free_faces(ball);
    RC_ASSERT(result.complex.total_size() == std::size_t{1});
  });
}
