// Exact sphere incidences of boundary vertices and the merging of vertices that are one
// exact point (sphere_incidence.hpp).

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "medial/sphere_incidence.hpp"
#include "medial/union_triangulation.hpp"
#include "rstruct/medial/boundary_vertices.hpp"

using namespace rstruct;
using namespace rstruct::medial;

namespace {

DistinctVertices distinct_of(const std::vector<Ball>& balls) {
  const auto rt = ball_triangulation(balls);
  return distinct_vertices(boundary_vertices(balls, rt, complex::dual_complex(rt)), balls, rt);
}

}  // namespace

TEST_CASE("four equal spheres with coplanar centres meet in two mirror points", "[medial]") {
  // Centres on the unit square in z = 0, r² = 0.5 + 0.0625: the spheres meet exactly in
  // (0.5, 0.5, ±0.25), irrational nowhere, but each point comes from up to four facets.
  const double r = std::sqrt(0.5625);
  const std::vector<Ball> balls{{{0, 0, 0}, r}, {{1, 0, 0}, r}, {{0, 1, 0}, r}, {{1, 1, 0}, r}};
  const DistinctVertices d = distinct_of(balls);
  REQUIRE(d.vertex.size() == 2);
  for (std::size_t v = 0; v < 2; ++v) {
    CHECK(d.on[v] == std::vector<std::uint32_t>{0, 1, 2, 3});
    CHECK(std::fabs(d.vertex[v].point.x - 0.5) < 1e-12);
    CHECK(std::fabs(std::fabs(d.vertex[v].point.z) - 0.25) < 1e-12);
  }
  CHECK(d.vertex[0].point.z * d.vertex[1].point.z < 0);  // the mirror twins stay apart
}

TEST_CASE("lies_on_sphere is exact where the rounded point is not", "[medial]") {
  // Spheres of radius √3 (not a double) around three corners of a cube: their common
  // points are irrational, and a fourth sphere through them is recognised exactly, while a
  // sphere 2⁻⁵⁰ larger is not.
  const double r = std::sqrt(3.0);
  const std::vector<Ball> balls{{{0, 0, 0}, r}, {{2, 0, 0}, r}, {{0, 2, 0}, r}};
  const auto bv = boundary_vertices_of_union(balls);
  REQUIRE(!bv.empty());
  for (const BoundaryVertex& v : bv) {
    // By symmetry the points are (1, 1, ±1): on the sphere of radius √3 around (2, 2, 0).
    CHECK(lies_on_sphere(v, balls, Ball{{2, 2, 0}, r}));
    CHECK_FALSE(lies_on_sphere(v, balls, Ball{{2, 2, 0}, r + std::ldexp(1.0, -50)}));
    CHECK_FALSE(lies_on_sphere(v, balls, Ball{{2, 2, 0.5}, r}));
    for (auto b : v.balls) CHECK(lies_on_sphere(v, balls, balls[b]));
  }
}
