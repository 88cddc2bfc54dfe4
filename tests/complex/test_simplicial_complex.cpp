#include "rstruct/complex/simplicial_complex.hpp"

#include <rapidcheck/catch.h>

#include <catch2/catch.hpp>

#include "complex/complex_test_support.hpp"
#include "complex/known_complexes.hpp"
#include "rstruct/complex/coface_index.hpp"
#include "rstruct/core/error.hpp"

using namespace rstruct::complex;
using rstruct::InvalidInput;

TEST_CASE("closure of a tetrahedron has all its faces") {
  const std::vector<Tetrahedron> tets = {{3, 1, 2, 0}};
  const auto k = SimplicialComplex::closure_of(tets);
  CHECK(k.size(0) == 4);
  CHECK(k.size(1) == 6);
  CHECK(k.size(2) == 4);
  CHECK(k.size(3) == 1);
  CHECK(k.dimension() == 3);
  CHECK(k.euler_characteristic() == 1);
  CHECK(k.is_valid());
  CHECK(k.tetrahedra()[0] == Tetrahedron{0, 1, 2, 3});
  // Face i omits vertex i.
  const auto& f = k.tetrahedron_faces(0);
  CHECK(k.triangles()[f[0]] == Triangle{1, 2, 3});
  CHECK(k.triangles()[f[3]] == Triangle{0, 1, 2});
  CHECK(k.find(Triangle{2, 0, 3}).has_value());
  CHECK(k.find(Edge{3, 0}).has_value());
  CHECK_FALSE(k.find(Edge{3, 4}).has_value());
  CHECK(k.find_vertex(2) == SimplexIndex{2});
  CHECK_FALSE(k.find_vertex(7).has_value());
}

TEST_CASE("empty complex") {
  const SimplicialComplex k;
  CHECK(k.dimension() == -1);
  CHECK(k.empty());
  CHECK(k.total_size() == 0);
  CHECK(k.is_valid());
  const auto closure = SimplicialComplex::closure_of(SimplexLists{});
  CHECK(closure.empty());
}

TEST_CASE("duplicates and unsorted tuples are merged") {
  SimplexLists lists;
  lists.triangles = {{2, 1, 0}, {0, 1, 2}, {1, 0, 2}};
  lists.edges = {{1, 0}, {7, 8}};
  lists.vertices = {9, 9, 0};
  const auto k = SimplicialComplex::closure_of(lists);
  CHECK(k.vertices() == std::vector<VertexId>{0, 1, 2, 7, 8, 9});
  CHECK(k.size(1) == 4);
  CHECK(k.size(2) == 1);
  CHECK(k.is_valid());
}

TEST_CASE("a repeated vertex in a simplex is rejected with its position") {
  SimplexLists lists;
  lists.triangles = {{0, 1, 2}, {4, 5, 4}};
  try {
    (void)SimplicialComplex::closure_of(lists);
    FAIL("no exception");
  } catch (const InvalidInput& e) {
    const std::string what = e.what();
    CHECK(what.find("triangle #1") != std::string::npos);
    CHECK(what.find("repeats vertex 4") != std::string::npos);
  }
}

TEST_CASE("explicit lists must be closed") {
  SimplexLists lists;
  lists.vertices = {0, 1, 2};
  lists.edges = {{0, 1}, {1, 2}};
  lists.triangles = {{0, 1, 2}};
  try {
    (void)SimplicialComplex::from_closed_lists(lists);
    FAIL("no exception");
  } catch (const InvalidInput& e) {
    CHECK(std::string(e.what()).find("(0, 2)") != std::string::npos);
  }
  lists.edges.push_back({2, 0});
  const auto k = SimplicialComplex::from_closed_lists(lists);
  CHECK(k.size(1) == 3);
  lists.vertices = {0, 1};
  CHECK_THROWS_AS(SimplicialComplex::from_closed_lists(lists), InvalidInput);
}

TEST_CASE("closed lists with sparse vertex ids, shuffled and repeated") {
  // Ids far apart (the lookups then search whole lists instead of a table by first
  // vertex), tuples in any order and listed twice: the same complex as closure_of.
  const auto base = SimplicialComplex::closure_of(testing::subdivided_box(2, 2, 1));
  const auto sparse = [](VertexId v) { return v * 1'000'003u + 11u; };
  SimplexLists lists;
  for (const VertexId v : base.vertices()) lists.vertices.push_back(sparse(v));
  for (const auto& e : base.edges()) lists.edges.push_back({sparse(e[1]), sparse(e[0])});
  for (const auto& t : base.triangles()) {
    lists.triangles.push_back({sparse(t[2]), sparse(t[0]), sparse(t[1])});
  }
  for (const auto& t : base.tetrahedra()) {
    lists.tetrahedra.push_back({sparse(t[3]), sparse(t[1]), sparse(t[2]), sparse(t[0])});
  }
  lists.triangles.push_back(lists.triangles.front());
  const auto expected = SimplicialComplex::closure_of(lists);
  for (const unsigned threads : {1u, 2u}) {
    const auto k = SimplicialComplex::from_closed_lists(lists, threads);
    CHECK(k.is_valid());
    CHECK(k.edges() == expected.edges());
    CHECK(k.triangles() == expected.triangles());
    CHECK(k.tetrahedra() == expected.tetrahedra());
    for (SimplexIndex t = 0; t < k.size(3); ++t) {
      CHECK(k.tetrahedron_faces(t) == expected.tetrahedron_faces(t));
    }
    SimplexLists missing = lists;
    missing.edges.erase(missing.edges.begin() + 3);
    CHECK_THROWS_AS(SimplicialComplex::from_closed_lists(missing, threads), InvalidInput);
  }
}

TEST_CASE("subcomplex keeps indices consistent and rejects non-closed selections") {
  const auto k = SimplicialComplex::closure_of(testing::tetrahedron_boundary());
  std::array<std::vector<bool>, 4> keep = {std::vector<bool>(4, true), std::vector<bool>(6, true),
                                           std::vector<bool>(4, true), {}};
  keep[2][k.find(Triangle{0, 1, 2}).value()] = false;
  const auto disk = k.subcomplex(keep);
  CHECK(disk.size(2) == 3);
  CHECK(disk.is_valid());
  keep[1][k.find(Edge{1, 2}).value()] = false;
  CHECK_THROWS_AS(k.subcomplex(keep), InvalidInput);
  keep[1].pop_back();
  CHECK_THROWS_AS(k.subcomplex(keep), InvalidInput);
}

TEST_CASE("coface index lists the cofaces of every simplex") {
  const auto k = SimplicialComplex::closure_of(testing::subdivided_box(2, 1, 1));
  const CofaceIndex cof(k);
  for (int d = 1; d <= 3; ++d) {
    std::size_t incidences = 0;
    for (SimplexIndex i = 0; i < k.size(d - 1); ++i) {
      const auto c = cof.cofaces(d - 1, i);
      incidences += c.size();
      for (std::size_t j = 0; j < c.size(); ++j) {
        if (j > 0) CHECK(c[j - 1] < c[j]);
        const auto faces = k.faces(d, c[j]);
        CHECK(std::find(faces.begin(), faces.end(), i) != faces.end());
      }
    }
    CHECK(incidences == k.size(d) * static_cast<std::size_t>(d + 1));
  }
}

TEST_CASE("random closures are valid and closed") {
  rc::prop("closure_of gives a valid complex that from_closed_lists accepts", [] {
    const auto lists = *testing::random_simplex_lists(8, 12);
    const auto k = SimplicialComplex::closure_of(lists);
    RC_ASSERT(k.is_valid());
    for (const auto& t : lists.tetrahedra) RC_ASSERT(k.find(t).has_value());
    for (const auto& t : lists.triangles) RC_ASSERT(k.find(t).has_value());
    for (const auto& e : lists.edges) RC_ASSERT(k.find(e).has_value());
    for (const auto v : lists.vertices) RC_ASSERT(k.find_vertex(v).has_value());
    SimplexLists explicit_lists;
    explicit_lists.vertices = k.vertices();
    explicit_lists.edges = k.edges();
    explicit_lists.triangles = k.triangles();
    explicit_lists.tetrahedra = k.tetrahedra();
    for (const unsigned threads : {1u, 2u}) {
      const auto again = SimplicialComplex::from_closed_lists(explicit_lists, threads);
      RC_ASSERT(again.is_valid());
      RC_ASSERT(again.vertices() == k.vertices());
      RC_ASSERT(again.edges() == k.edges());
      RC_ASSERT(again.triangles() == k.triangles());
      RC_ASSERT(again.tetrahedra() == k.tetrahedra());
    }
  });
}
