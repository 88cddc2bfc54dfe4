#include "rstruct/complex/manifold.hpp"

#include <rapidcheck/catch.h>

#include <catch2/catch.hpp>
#include <map>

#include "complex/complex_test_support.hpp"
#include "complex/known_complexes.hpp"
#include "rstruct/core/error.hpp"

using namespace rstruct::complex;

namespace {

/// Independent check of an orientation: every directed edge appears at most once, and
/// every edge shared by two triangles appears in both directions.
bool is_consistently_oriented(const std::vector<Triangle>& triangles) {
  std::map<std::pair<VertexId, VertexId>, int> directed;
  for (const auto& t : triangles) {
    for (int i = 0; i < 3; ++i) {
      if (++directed[{t[i], t[(i + 1) % 3]}] > 1) return false;
    }
  }
  return true;
}

/// The oriented triangles have the same vertex sets as the complex's triangles.
bool same_triangles(const SimplicialComplex& k, const std::vector<Triangle>& oriented) {
  if (oriented.size() != k.size(2)) return false;
  for (std::size_t i = 0; i < oriented.size(); ++i) {
    Triangle t = oriented[i];
    std::sort(t.begin(), t.end());
    if (t != k.triangles()[i]) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("closed surfaces are closed 2-manifolds") {
  for (const auto& triangles : {testing::tetrahedron_boundary(), testing::octahedron(),
                                testing::torus7(), testing::genus2(), testing::klein_bottle(),
                                testing::projective_plane6(),
                                testing::boundary_triangles(testing::subdivided_box(3, 2, 2))}) {
    const auto check = check_closed_2_manifold(SimplicialComplex::closure_of(triangles));
    INFO(check.first_problem);
    CHECK(check.is_closed_2_manifold);
  }
}

TEST_CASE("what is not a closed 2-manifold, and why") {
  SECTION("a disk has boundary edges") {
    auto tris = testing::tetrahedron_boundary();
    tris.pop_back();
    const auto check = check_closed_2_manifold(SimplicialComplex::closure_of(tris));
    CHECK_FALSE(check.is_closed_2_manifold);
    CHECK(check.edges_not_in_two_triangles == 3);
  }
  SECTION("a fin: one edge in three triangles") {
    auto tris = testing::tetrahedron_boundary();
    tris.push_back({0, 1, 9});
    const auto check = check_closed_2_manifold(SimplicialComplex::closure_of(tris));
    CHECK_FALSE(check.is_closed_2_manifold);
    CHECK(check.edges_not_in_two_triangles == 3);  // 01 in three, 09 and 19 in one
    CHECK(check.first_problem.find("edge") != std::string::npos);
  }
  SECTION("two spheres pinched at a vertex") {
    auto tris = testing::tetrahedron_boundary();
    for (auto t : testing::tetrahedron_boundary()) {
      for (auto& v : t) v = v == 0 ? 0 : v + 10;
      tris.push_back(t);
    }
    const auto check = check_closed_2_manifold(SimplicialComplex::closure_of(tris));
    CHECK_FALSE(check.is_closed_2_manifold);
    CHECK(check.edges_not_in_two_triangles == 0);
    CHECK(check.vertices_with_bad_link == 1);
    CHECK(check.first_problem.find("vertex 0") != std::string::npos);
  }
  SECTION("solids, isolated vertices and the empty complex") {
    CHECK_FALSE(is_closed_2_manifold(
        SimplicialComplex::closure_of(testing::subdivided_box(1, 1, 1))));
    SimplexLists lists;
    lists.triangles = testing::octahedron();
    lists.vertices = {99};
    const auto check = check_closed_2_manifold(SimplicialComplex::closure_of(lists));
    CHECK(check.vertices_with_bad_link == 1);
    CHECK_FALSE(is_closed_2_manifold(SimplicialComplex{}));
  }
}

TEST_CASE("orientable surfaces get a consistent orientation") {
  for (const auto& triangles : {testing::tetrahedron_boundary(), testing::octahedron(),
                                testing::torus7(), testing::genus2(),
                                testing::boundary_triangles(testing::subdivided_box(2, 3, 1))}) {
    const auto k = SimplicialComplex::closure_of(triangles);
    const auto oriented = orient_triangles(k);
    REQUIRE(oriented.has_value());
    CHECK(same_triangles(k, *oriented));
    CHECK(is_consistently_oriented(*oriented));
  }
}

TEST_CASE("non-orientable surfaces are detected") {
  CHECK_FALSE(orient_triangles(SimplicialComplex::closure_of(testing::klein_bottle())));
  CHECK_FALSE(orient_triangles(SimplicialComplex::closure_of(testing::projective_plane6())));
  // A Möbius strip (5 triangles) is a surface with boundary and not orientable.
  const std::vector<Triangle> mobius = {{0, 1, 2}, {1, 2, 3}, {2, 3, 4}, {3, 4, 0}, {4, 0, 1}};
  CHECK_FALSE(orient_triangles(SimplicialComplex::closure_of(mobius)));
  // An annulus is orientable.
  const std::vector<Triangle> annulus = {{0, 1, 3}, {1, 3, 4}, {1, 2, 4}, {2, 4, 5},
                                         {2, 0, 5}, {0, 5, 3}};
  const auto oriented = orient_triangles(SimplicialComplex::closure_of(annulus));
  REQUIRE(oriented.has_value());
  CHECK(is_consistently_oriented(*oriented));
}

TEST_CASE("orienting a non-manifold edge throws") {
  auto tris = testing::tetrahedron_boundary();
  tris.push_back({0, 1, 9});
  CHECK_THROWS_AS(orient_triangles(SimplicialComplex::closure_of(tris)), rstruct::InvalidInput);
}

TEST_CASE("orientation is invariant under relabelling") {
  rc::prop("a relabelled torus stays an orientable closed 2-manifold", [] {
    const auto k = SimplicialComplex::closure_of(testing::genus2());
    const auto ids = *testing::random_injective_ids(k.size(0));
    const auto r = SimplicialComplex::closure_of(testing::relabelled(
        k, [&](VertexId v) { return ids[k.find_vertex(v).value()]; }));
    RC_ASSERT(is_closed_2_manifold(r));
    const auto oriented = orient_triangles(r);
    RC_ASSERT(oriented.has_value());
    RC_ASSERT(is_consistently_oriented(*oriented));
  });
  rc::prop("a relabelled Klein bottle stays non-orientable", [] {
    const auto k = SimplicialComplex::closure_of(testing::klein_bottle());
    const auto ids = *testing::random_injective_ids(k.size(0));
    const auto r = SimplicialComplex::closure_of(testing::relabelled(
        k, [&](VertexId v) { return ids[k.find_vertex(v).value()]; }));
    RC_ASSERT(is_closed_2_manifold(r));
    RC_ASSERT(!orient_triangles(r).has_value());
  });
}
