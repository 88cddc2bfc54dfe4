// remove_duplicate_vertices against a brute-force oracle: the first of each group of equal
// points is kept in order, properties follow their vertex, faces are re-indexed.

#include <rapidcheck/catch.h>

#include <catch2/catch.hpp>

#include "io/mesh_generators.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/io/mesh_io.hpp"

using rstruct::Point3;
using rstruct::TriangleMesh;
using namespace rstruct::io;
using namespace rstruct::io::testing;

TEST_CASE("duplicate removal matches a brute-force oracle") {
  rc::prop("oracle", [] {
    TriangleMesh m = *mesh();
    // Force some duplicates: copy random vertices over others.
    const std::size_t n = m.vertices.size();
    const int copies = *rc::gen::inRange(0, 10);
    for (int c = 0; c < copies; ++c) {
      const auto from = *rc::gen::inRange<std::size_t>(0, n);
      const auto to = *rc::gen::inRange<std::size_t>(0, n);
      m.vertices[to] = m.vertices[from];
    }
    const TriangleMesh original = m;
    // Oracle: quadratic scan with == on doubles.
    std::vector<std::uint32_t> expected_map(n);
    std::vector<std::size_t> kept;
    for (std::size_t i = 0; i < n; ++i) {
      std::size_t j = 0;
      while (j < kept.size() && !(original.vertices[kept[j]] == original.vertices[i])) ++j;
      if (j == kept.size()) kept.push_back(i);
      expected_map[i] = static_cast<std::uint32_t>(j);
    }
    RC_ASSERT(count_duplicate_vertices(m) == n - kept.size());
    std::vector<std::uint32_t> map;
    const std::size_t removed = remove_duplicate_vertices(m, &map);
    RC_ASSERT(removed == n - kept.size());
    RC_ASSERT(map == expected_map);
    RC_ASSERT(m.vertices.size() == kept.size());
    for (std::size_t j = 0; j < kept.size(); ++j) {
      for (std::size_t k = 0; k < 3; ++k) {
        RC_ASSERT(same_bits(m.vertices[j][k], original.vertices[kept[j]][k]));
      }
      for (std::size_t p = 0; p < m.vertex_properties.size(); ++p) {
        RC_ASSERT(same_bits(m.vertex_properties[p].second[j],
                            original.vertex_properties[p].second[kept[j]]));
      }
    }
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
      for (std::size_t k = 0; k < 3; ++k) {
        RC_ASSERT(m.faces[f][k] == expected_map[original.faces[f][k]]);
      }
    }
    RC_ASSERT(count_duplicate_vertices(m) == 0u);
  });
}

TEST_CASE("0.0 and -0.0 are the same point; the first one is kept") {
  TriangleMesh m;
  m.vertices = {{0.0, 1, 2}, {-0.0, 1, 2}, {0.0, 1, 2.0000000000000004}};
  m.faces = {{0, 1, 2}};
  CHECK(remove_duplicate_vertices(m) == 1);
  REQUIRE(m.vertices.size() == 2);
  CHECK(!std::signbit(m.vertices[0].x));
  CHECK(m.faces[0] == std::array<std::uint32_t, 3>{0, 0, 1});
}

TEST_CASE("duplicate removal rejects a malformed mesh instead of reading out of bounds") {
  TriangleMesh m;
  m.vertices = {{0, 0, 0}};
  m.faces = {{0, 0, 1}};
  CHECK_THROWS_AS(remove_duplicate_vertices(m), rstruct::InvalidInput);
  m.faces.clear();
  m.vertex_properties.emplace_back("radius", std::vector<double>{});
  CHECK_THROWS_AS(remove_duplicate_vertices(m), rstruct::InvalidInput);
}
