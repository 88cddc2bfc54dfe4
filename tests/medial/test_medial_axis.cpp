// Medial axis of a union of balls: hand-derived complexes, random unions (Betti numbers,
// containment, medial balls, two nearest boundary points) and degenerate unions.

#include "rstruct/medial/medial_axis.hpp"

#include <rapidcheck/catch.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <ostream>
#include <set>
#include <vector>

#include "medial/medial_test_support.hpp"
#include "rstruct/complex/dual_complex.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/medial/boundary_vertices.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"

using namespace rstruct;
using namespace rstruct::medial;

namespace rstruct {
// Counter-examples print in hexfloat so that the bits survive.
inline void showValue(const Ball& b, std::ostream& os) {
  os << std::hexfloat << "{{" << b.c.x << ", " << b.c.y << ", " << b.c.z << "}, " << b.r << "}"
     << std::defaultfloat;
}
}  // namespace rstruct

namespace {

complex::BettiNumbers betti(const MedialAxis& axis) {
  return complex::betti_numbers(axis.simplicial_complex());
}

std::set<std::uint32_t> centre_sources(const MedialAxis& axis) {
  std::set<std::uint32_t> out;
  for (std::size_t v = 0; v < axis.vertices.size(); ++v) {
    if (axis.kind[v] == MedialVertexKind::ball_centre) out.insert(axis.source[v]);
  }
  return out;
}

/// The vertex that is the centre of ball `b`.
std::uint32_t centre_vertex(const MedialAxis& axis, std::uint32_t b) {
  for (std::uint32_t v = 0; v < axis.vertices.size(); ++v) {
    if (axis.kind[v] == MedialVertexKind::ball_centre && axis.source[v] == b) return v;
  }
  FAIL("no vertex at the centre of ball " << b);
  return 0;
}

std::array<std::uint32_t, 2> edge(std::uint32_t a, std::uint32_t b) {
  return {std::min(a, b), std::max(a, b)};
}

/// Random union of balls on a coarse dyadic grid (so that degeneracies do occur).
rc::Gen<std::vector<Ball>> random_union(int min_size, int max_size) {
  return rc::gen::withSize([=](int) {
    return rc::gen::mapcat(rc::gen::inRange(min_size, max_size + 1), [](int n) {
      return rc::gen::container<std::vector<Ball>>(
          static_cast<std::size_t>(n),
          rc::gen::map(rc::gen::tuple(rc::gen::inRange(0, 1 << 12), rc::gen::inRange(0, 1 << 12),
                                      rc::gen::inRange(0, 1 << 12), rc::gen::inRange(1, 1 << 10)),
                       [n](const std::tuple<int, int, int, int>& t) {
                         // Box side grows like n^(1/3) so the density stays comparable.
                         const double side = 4.0 * std::cbrt(static_cast<double>(n));
                         const double s = side / (1 << 12);
                         return Ball{{std::get<0>(t) * s, std::get<1>(t) * s, std::get<2>(t) * s},
                                     0.6 + std::get<3>(t) * (1.0 / (1 << 10))};
                       }));
    });
  });
}

}  // namespace

TEST_CASE("one ball: its centre", "[medial]") {
  const std::vector<Ball> balls{{{1, 2, 3}, 0.5}};
  const MedialAxis axis = medial_axis_of_union(balls);
  REQUIRE(axis.vertices.size() == 1);
  CHECK(axis.vertices[0] == Point3{1, 2, 3});
  CHECK(axis.radius[0] == 0.5);
  CHECK(axis.edges.empty());
  CHECK(axis.faces.empty());
  CHECK(axis.isolated_vertices == std::vector<std::uint32_t>{0});
}

TEST_CASE("two overlapping balls: the segment of the centres", "[medial]") {
  const std::vector<Ball> balls{{{0, 0, 0}, 1.0}, {{1.5, 0, 0}, 0.75}};
  const MedialAxis axis = medial_axis_of_union(balls);
  REQUIRE(axis.vertices.size() == 2);
  CHECK(axis.faces.empty());
  REQUIRE(axis.all_edges().size() == 1);
  CHECK(axis.all_edges()[0] == edge(centre_vertex(axis, 0), centre_vertex(axis, 1)));
  CHECK(axis.radius[centre_vertex(axis, 1)] == 0.75);
}

TEST_CASE("two disjoint balls: two centres", "[medial]") {
  const std::vector<Ball> balls{{{0, 0, 0}, 1.0}, {{3, 0, 0}, 1.0}};
  const MedialAxis axis = medial_axis_of_union(balls);
  CHECK(axis.vertices.size() == 2);
  CHECK(axis.isolated_vertices.size() == 2);
  CHECK(betti(axis) == complex::BettiNumbers{{2, 0, 0, 0}});
}

TEST_CASE("three balls in a row: two segments", "[medial]") {
  const std::vector<Ball> balls{{{0, 0, 0}, 1.0}, {{1.5, 0.1, 0}, 1.0}, {{3, 0, 0.1}, 1.0}};
  const MedialAxis axis = medial_axis_of_union(balls);
  REQUIRE(axis.vertices.size() == 3);
  CHECK(axis.faces.empty());
  const auto e = axis.all_edges();
  REQUIRE(e.size() == 2);
  CHECK(std::count(e.begin(), e.end(), edge(centre_vertex(axis, 0), centre_vertex(axis, 1))) == 1);
  CHECK(std::count(e.begin(), e.end(), edge(centre_vertex(axis, 1), centre_vertex(axis, 2))) == 1);
}

TEST_CASE("three balls in a triangle: the triangle of the centres", "[medial]") {
  const std::vector<Ball> balls{{{0, 0, 0}, 1.3}, {{2, 0, 0}, 1.3}, {{1, 1.75, 0}, 1.3}};
  const MedialAxis axis = medial_axis_of_union(balls);
  REQUIRE(axis.vertices.size() == 3);
  CHECK(centre_sources(axis) == std::set<std::uint32_t>{0, 1, 2});
  REQUIRE(axis.faces.size() == 1);
  CHECK(axis.faces[0].size() == 3);
  CHECK(axis.all_edges().size() == 3);
}

TEST_CASE("four balls around a tetrahedron: cone from one vertex over the six edges",
          "[medial]") {
  const std::vector<Ball> balls{
      {{1, 1, 1}, 1.8}, {{1, -1, -1}, 1.8}, {{-1, 1, -1}, 1.8}, {{-1, -1, 1}, 1.8}};
  MedialAxis axis = medial_axis_of_union(balls);
  // 4 centres + the Voronoi vertex of the four boundary points (the origin, by symmetry).
  REQUIRE(axis.vertices.size() == 5);
  CHECK(centre_sources(axis) == std::set<std::uint32_t>{0, 1, 2, 3});
  std::uint32_t apex = 0;
  while (axis.kind[apex] == MedialVertexKind::ball_centre) ++apex;
  CHECK(norm(axis.vertices[apex]) < 1e-12);
  REQUIRE(axis.faces.size() == 6);
  for (const auto& f : axis.faces) {
    REQUIRE(f.size() == 3);
    CHECK(std::count(f.begin(), f.end(), apex) == 1);
  }
  CHECK(axis.all_edges().size() == 10);
  CHECK(betti(axis) == complex::BettiNumbers{{1, 0, 0, 0}});
}

TEST_CASE("a ring of balls: a cycle through the centres", "[medial]") {
  std::vector<Ball> balls;
  const int n = 8;
  const double pi = std::acos(-1.0);
  for (int i = 0; i < n; ++i) {
    const double a = 2 * pi * i / n;
    balls.push_back({{4 * std::cos(a), 4 * std::sin(a), 0.0}, 1.7});
  }
  const MedialAxis axis = medial_axis_of_union(balls);
  REQUIRE(axis.vertices.size() == n);
  CHECK(axis.faces.empty());
  const auto e = axis.all_edges();
  REQUIRE(e.size() == n);
  for (int i = 0; i < n; ++i) {
    const auto expected =
        edge(centre_vertex(axis, i), centre_vertex(axis, static_cast<std::uint32_t>((i + 1) % n)));
    CHECK(std::count(e.begin(), e.end(), expected) == 1);
  }
  CHECK(betti(axis) == complex::BettiNumbers{{1, 1, 0, 0}});
}

TEST_CASE("a ring of balls with triple overlaps: Betti numbers of a circle", "[medial]") {
  std::vector<Ball> balls;
  const int n = 12;
  const double pi = std::acos(-1.0);
  for (int i = 0; i < n; ++i) {
    const double a = 2 * pi * i / n;
    balls.push_back({{4 * std::cos(a), 4 * std::sin(a), 0.1 * (i % 3)}, 2.0});
  }
  const MedialAxis axis = medial_axis_of_union(balls);
  CHECK(betti(axis) == complex::BettiNumbers{{1, 1, 0, 0}});
}

TEST_CASE("bad balls are rejected", "[medial]") {
  const std::vector<Ball> zero{{{0, 0, 0}, 0.0}};
  CHECK_THROWS_AS(medial_axis_of_union(zero), InvalidInput);
  const std::vector<Ball> nan{{{0, std::nan(""), 0}, 1.0}};
  CHECK_THROWS_AS(medial_axis_of_union(nan), InvalidInput);
  CHECK(medial_axis_of_union(std::vector<Ball>{}).vertices.empty());
}

TEST_CASE("random unions: topology, containment, medial balls", "[medial][rapidcheck]") {
  rc::prop("axis of 5-200 balls", [] {
    const std::vector<Ball> balls = *random_union(5, 200);
    MedialAxisStats stats;
    const MedialAxis axis = medial_axis_of_union(balls, &stats);
    std::string problem;
    RC_ASSERT(axis.is_valid(&problem));
    RC_ASSERT(betti(axis) == stats.betti_k);
    // Round-off allowance: the constructions are a few double operations on coordinates of
    // size `extent`; 1e-9·extent is far above their error and far below any feature.
    const double tol = 1e-9 * testing::union_extent(balls);
    for (std::size_t v = 0; v < axis.vertices.size(); ++v) {
      RC_ASSERT(testing::union_depth(balls, axis.vertices[v]) >= -tol);
    }
    // Medial balls lie in the union: sample 32 points of each medial sphere.
    static const std::vector<Vec3> dirs = testing::sphere_directions(32);
    for (std::size_t v = 0; v < axis.vertices.size(); v += 7) {
      for (const Vec3& d : dirs) {
        const Point3 p = axis.vertices[v] + axis.radius[v] * d;
        RC_ASSERT(testing::union_depth(balls, p) >= -1e-7 * testing::union_extent(balls));
      }
    }
  });
}

TEST_CASE("random unions: points of medial faces have two nearest boundary points",
          "[medial][rapidcheck]") {
  rc::prop("two nearest points", [] {
    const std::vector<Ball> balls = *random_union(5, 60);
    const MedialAxis axis = medial_axis_of_union(balls);
    const auto v = boundary_vertices_of_union(balls);
    // Stated tolerance: 1e-7 times the extent (constructions are rounded doubles).
    const double tol = 1e-7 * testing::union_extent(balls);
    static const std::vector<Vec3> dirs = testing::sphere_directions(24);
    for (const auto& t : axis.triangles()) {
      const Point3 x = (axis.vertices[t[0]] + axis.vertices[t[1]] + axis.vertices[t[2]]) / 3.0;
      double d1 = HUGE_VAL, d2 = HUGE_VAL;
      for (const BoundaryVertex& b : v) {
        const double d = distance(x, b.point);
        if (d < d1) {
          d2 = d1;
          d1 = d;
        } else if (d < d2) {
          d2 = d;
        }
      }
      // Two boundary vertices at the same distance d1 ...
      RC_ASSERT(d2 - d1 <= tol);
      // ... and B(x, d1) inside the union, so d1 is the distance to the boundary and both
      // are nearest boundary points.
      for (const Vec3& d : dirs) {
        RC_ASSERT(testing::union_depth(balls, x + d1 * d) >= -tol);
      }
    }
  });
}
