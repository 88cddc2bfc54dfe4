#include "rstruct/complex/homology.hpp"

#include <rapidcheck/catch.h>

#include <catch2/catch.hpp>

#include "complex/complex_test_support.hpp"
#include "complex/known_complexes.hpp"

using namespace rstruct::complex;
using testing::dense_betti;

namespace {

BettiNumbers betti(long long b0, long long b1, long long b2, long long b3 = 0) {
  return BettiNumbers{{b0, b1, b2, b3}};
}

/// Checks both methods and the dense oracle against the expected numbers.
void check_betti(const SimplicialComplex& k, const BettiNumbers& expected) {
  INFO("complex with " << k.size(0) << " vertices, " << k.size(1) << " edges, "
                       << k.size(2) << " triangles, " << k.size(3) << " tetrahedra");
  CHECK(betti_numbers(k, HomologyMethod::reduction) == expected);
  CHECK(betti_numbers(k, HomologyMethod::coreduction_then_reduction) == expected);
  if (k.total_size() < 2000) CHECK(dense_betti(k) == expected);
  CHECK(expected.euler_characteristic() == k.euler_characteristic());
}

}  // namespace

TEST_CASE("Betti numbers of spheres") {
  check_betti(SimplicialComplex::closure_of(testing::tetrahedron_boundary()), betti(1, 0, 1));
  check_betti(SimplicialComplex::closure_of(testing::octahedron()), betti(1, 0, 1));
}

TEST_CASE("Betti numbers of the 7-vertex torus and the genus-2 surface") {
  check_betti(SimplicialComplex::closure_of(testing::torus7()), betti(1, 2, 1));
  check_betti(SimplicialComplex::closure_of(testing::genus2()), betti(1, 4, 1));
}

TEST_CASE("Z2 Betti numbers of non-orientable surfaces") {
  check_betti(SimplicialComplex::closure_of(testing::klein_bottle()), betti(1, 2, 1));
  check_betti(SimplicialComplex::closure_of(testing::projective_plane6()), betti(1, 1, 1));
}

TEST_CASE("Betti numbers of a solid ball and its boundary sphere") {
  const auto tets = testing::subdivided_box(2, 2, 2);
  const auto ball = SimplicialComplex::closure_of(tets);
  CHECK(ball.size(0) == 27);
  CHECK(ball.size(3) == 48);
  check_betti(ball, betti(1, 0, 0));
  const auto sphere = SimplicialComplex::closure_of(testing::boundary_triangles(tets));
  CHECK(sphere.size(0) == 26);
  check_betti(sphere, betti(1, 0, 1));
  check_betti(SimplicialComplex::closure_of(testing::subdivided_box(4, 3, 2)), betti(1, 0, 0));
}

TEST_CASE("Betti numbers of graphs, points and disjoint unions") {
  check_betti(SimplicialComplex::closure_of(testing::wedge_of_three_circles()), betti(1, 3, 0));
  SimplexLists points;
  points.vertices = {5, 1, 9};
  check_betti(SimplicialComplex::closure_of(points), betti(3, 0, 0));
  // Sphere ⊔ torus ⊔ an isolated point.
  SimplexLists lists;
  for (auto t : testing::tetrahedron_boundary()) lists.triangles.push_back(t);
  for (auto t : testing::torus7()) {
    for (auto& v : t) v += 100;
    lists.triangles.push_back(t);
  }
  lists.vertices.push_back(1000);
  check_betti(SimplicialComplex::closure_of(lists), betti(3, 2, 2));
  check_betti(SimplicialComplex{}, betti(0, 0, 0));
}

TEST_CASE("a closed 3-manifold piece: boundary of the 4-simplex has beta3 = 0, hollow ball") {
  // The boundary of a 4-simplex needs dimension 4 simplices to be filled: its 3-skeleton
  // (five tetrahedra) is a 3-sphere: β = (1, 0, 0, 1).
  const std::vector<Tetrahedron> tets = {
      {0, 1, 2, 3}, {0, 1, 2, 4}, {0, 1, 3, 4}, {0, 2, 3, 4}, {1, 2, 3, 4}};
  check_betti(SimplicialComplex::closure_of(tets), betti(1, 0, 0, 1));
}

TEST_CASE("sparse ranks agree with dense elimination on random complexes") {
  rc::prop("boundary ranks and Betti numbers match the dense oracle", [] {
    const auto k = SimplicialComplex::closure_of(*testing::random_simplex_lists(9, 40));
    const auto ranks = boundary_ranks(k);
    for (int d = 1; d <= 3; ++d) {
      RC_ASSERT(ranks[d] == testing::dense_z2_rank(testing::dense_boundary(k, d)));
    }
    const auto expected = dense_betti(k);
    RC_ASSERT(betti_numbers(k, HomologyMethod::reduction) == expected);
    RC_ASSERT(betti_numbers(k, HomologyMethod::coreduction_then_reduction) == expected);
  });
}

TEST_CASE("Euler characteristic is the alternating sum of Betti numbers") {
  rc::prop("chi = b0 - b1 + b2 - b3", [] {
    const auto k = SimplicialComplex::closure_of(*testing::random_simplex_lists(12, 60));
    RC_ASSERT(betti_numbers(k).euler_characteristic() == k.euler_characteristic());
  });
}

TEST_CASE("Betti numbers do not depend on vertex labels") {
  rc::prop("relabelling the vertices injectively keeps the Betti numbers", [] {
    const auto k = SimplicialComplex::closure_of(*testing::random_simplex_lists(10, 40));
    const auto ids = *testing::random_injective_ids(k.size(0));
    const auto relabelled = SimplicialComplex::closure_of(testing::relabelled(
        k, [&](VertexId v) { return ids[k.find_vertex(v).value()]; }));
    RC_ASSERT(relabelled.is_valid());
    RC_ASSERT(betti_numbers(relabelled) == betti_numbers(k));
    RC_ASSERT(betti_numbers(relabelled, HomologyMethod::reduction) == betti_numbers(k));
  });
  rc::prop("relabelled known surfaces keep their Betti numbers", [] {
    const auto k = SimplicialComplex::closure_of(testing::genus2());
    const auto ids = *testing::random_injective_ids(k.size(0));
    const auto relabelled = SimplicialComplex::closure_of(testing::relabelled(
        k, [&](VertexId v) { return ids[k.find_vertex(v).value()]; }));
    RC_ASSERT(betti_numbers(relabelled, HomologyMethod::reduction) == betti(1, 4, 1));
    RC_ASSERT(betti_numbers(relabelled) == betti(1, 4, 1));
  });
}

TEST_CASE("coreduction leaves little to reduce on a surface") {
  HomologyStats stats;
  const auto k = SimplicialComplex::closure_of(testing::genus2());
  CHECK(betti_numbers(k, HomologyMethod::coreduction_then_reduction, &stats) == betti(1, 4, 1));
  CHECK(stats.coreduction_pairs > 0);
  CHECK(stats.cells_reduced[0] == 0);
  CHECK(stats.cells_reduced[1] + stats.cells_reduced[2] < k.size(1) + k.size(2));
}
