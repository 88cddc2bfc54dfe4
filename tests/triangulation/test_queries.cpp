// Queries against brute force: incident cells, adjacency, hull, locate, nearest vertex in
// power distance, the power cell and the duals; constructions against their definitions.
#include <rapidcheck/catch.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <gmpxx.h>
#include <random>

#include "generators.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/predicates/predicates.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"

namespace {

using rstruct::Point3;
using rstruct::Sign;
using rstruct::triangulation::CellId;
using rstruct::triangulation::Edge;
using rstruct::triangulation::Facet;
using rstruct::triangulation::kInfiniteVertex;
using rstruct::triangulation::RegularTriangulation3;
using rstruct::triangulation::VertexId;
namespace pr = rstruct::predicates;

RegularTriangulation3 draw(int kind, std::uint64_t seed, std::size_t n) {
  using namespace rstruct::test;
  switch (kind) {
    case 0: return RegularTriangulation3(uniform_points(n, seed));
    case 1: return RegularTriangulation3(uniform_points(n, seed), hiding_weights(n, 0.2, seed));
    case 2: return RegularTriangulation3(grid_points(4, 3, 5));
    default: return RegularTriangulation3(sphere_points(50));
  }
}

bool contains(const RegularTriangulation3& t, CellId c, const Point3& q) {
  const int inf = t.index(c, kInfiniteVertex);
  for (int i = 0; i < 4; ++i) {
    if (inf >= 0 && i != inf) continue;  // the region of an infinite cell: beyond its facet
    const Point3* p[4];
    for (int j = 0; j < 4; ++j) p[j] = i == j ? &q : &t.point(t.vertex(c, j));
    const Sign o = pr::orient3d(*p[0], *p[1], *p[2], *p[3]);
    if (inf >= 0 ? o != Sign::positive : o == Sign::negative) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("incident cells, adjacency and hull membership match brute force") {
  rc::prop("queries", [] {
    const int kind = *rc::gen::inRange(0, 4);
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    const auto n = static_cast<std::size_t>(*rc::gen::inRange(5, 120));
    const RegularTriangulation3 t = draw(kind, seed, n);
    std::size_t hull_facets = 0;
    t.for_each_cell([&](CellId c) { hull_facets += t.is_infinite(c); });
    RC_ASSERT(t.convex_hull_facets().size() == hull_facets);
    for (VertexId v = 0; v < t.number_of_points(); ++v) {
      if (!t.is_vertex(v)) {
        RC_ASSERT(t.incident_cell(v) == rstruct::triangulation::kNoCell);
        continue;
      }
      std::vector<CellId> expected;
      std::set<VertexId> adjacent;
      bool on_hull = false;
      t.for_each_cell([&](CellId c) {
        if (t.index(c, v) < 0) return;
        expected.push_back(c);
        for (const VertexId u : t.vertices(c)) {
          if (u != v && u != kInfiniteVertex) adjacent.insert(u);
          on_hull |= u == kInfiniteVertex;
        }
      });
      std::vector<CellId> got = t.incident_cells(v);
      std::sort(got.begin(), got.end());
      RC_ASSERT(got == expected);
      const std::vector<VertexId> adj = t.adjacent_vertices(v);
      RC_ASSERT(std::set<VertexId>(adj.begin(), adj.end()) == adjacent);
      RC_ASSERT(t.is_on_convex_hull(v) == on_hull);
      for (const CellId c : t.power_cell_vertices(v)) {
        RC_ASSERT(!t.is_infinite(c));
        RC_ASSERT(t.index(c, v) >= 0);
      }
    }
    for (const Facet& f : t.convex_hull_facets()) {
      RC_ASSERT(!t.is_infinite(f.cell));
      RC_ASSERT(t.is_infinite(t.neighbor(f.cell, f.index)));
      const auto tri = t.facet_vertices(f);
      for (VertexId v = 0; v < t.number_of_points(); ++v) {  // all points inside or on
        RC_ASSERT(pr::orient3d(t.point(tri[0]), t.point(tri[1]), t.point(tri[2]),
                               t.point(v)) != Sign::positive);
      }
    }
  });
}

TEST_CASE("edges: the cells around an edge close up and all contain it") {
  const RegularTriangulation3 t(rstruct::test::uniform_points(60, 5));
  t.for_each_finite_cell([&](CellId c) {
    for (int i = 0; i < 4; ++i) {
      for (int j = i + 1; j < 4; ++j) {
        const auto ring = t.dual(Edge{c, i, j});
        REQUIRE(ring.size() >= 3);
        for (const CellId d : ring) {
          CHECK(t.index(d, t.vertex(c, i)) >= 0);
          CHECK(t.index(d, t.vertex(c, j)) >= 0);
        }
      }
    }
  });
}

TEST_CASE("locate and nearest power vertex match brute force") {
  rc::prop("queries at random points", [] {
    const int kind = *rc::gen::inRange(0, 4);
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    const auto n = static_cast<std::size_t>(*rc::gen::inRange(5, 150));
    const RegularTriangulation3 t = draw(kind, seed, n);
    rstruct::test::Random r(seed ^ 77);
    for (int k = 0; k < 30; ++k) {
      // Queries inside, around and far outside the input, and at input points.
      Point3 q{r.uniform() * 8 - 3, r.uniform() * 8 - 3, r.uniform() * 8 - 3};
      if (k % 5 == 0) q = t.point(static_cast<VertexId>(r.next() % t.number_of_points()));
      const CellId c = t.locate(q);
      RC_ASSERT(contains(t, c, q));
      const VertexId v = t.nearest_power_vertex(q, c);
      RC_ASSERT(t.is_vertex(v));
      for (VertexId u = 0; u < t.number_of_points(); ++u) {
        RC_ASSERT(pr::compare_power_distance(q, t.weighted_point(u), t.weighted_point(v)) !=
                  Sign::negative);
      }
    }
  });
}

TEST_CASE("orthocentres are orthogonal to their cell's weighted vertices") {
  const std::size_t n = 200;
  const RegularTriangulation3 t(rstruct::test::uniform_points(n, 11),
                                rstruct::test::hiding_weights(n, 0.01, 12));
  t.for_each_finite_cell([&](CellId c) {
    const Point3 z = t.orthocenter(c);
    const double r2 = t.squared_orthoradius(c);
    const Point3 zc = t.circumcenter(c);
    const double rc2 = t.squared_circumradius(c);
    for (const VertexId v : t.vertices(c)) {
      // Measurements: relative accuracy of a double construction on a well-shaped input.
      const double scale = 1 + std::fabs(r2) + squared_distance(z, t.point(v));
      CHECK(std::fabs(squared_distance(z, t.point(v)) - t.weight(v) - r2) <= 1e-6 * scale);
      CHECK(std::fabs(squared_distance(zc, t.point(v)) - rc2) <= 1e-6 * (1 + rc2));
    }
  });
  // Dual of a finite facet joins the two orthocentres; a hull facet gives an outward ray.
  for (const Facet& f : t.convex_hull_facets()) {
    const auto d = t.dual(f);
    CHECK(d.is_ray);
    const auto tri = t.facet_vertices(f);
    const Point3 far = t.point(tri[0]) + d.direction;
    CHECK(pr::orient3d(t.point(tri[0]), t.point(tri[1]), t.point(tri[2]), far) ==
          Sign::positive);
  }
  const CellId c = t.finite_cells().front();
  for (int i = 0; i < 4; ++i) {
    const Facet f{c, i};
    if (t.is_infinite(t.neighbor(c, i))) continue;
    const auto d = t.dual(f);
    CHECK(!d.is_ray);
    CHECK(d.source == t.orthocenter(c));
    CHECK(d.target == t.orthocenter(t.neighbor(c, i)));
  }
}

namespace {

/// Exact orthocentre of four weighted points by Gaussian elimination over the rationals on
/// 2 (p_i − p_0)·x = |p_i|² − w_i − |p_0|² + w_0, i = 1..3 (written independently of the
/// library's Cramer formula), rounded once per coordinate.
Point3 exact_orthocenter(const std::array<Point3, 4>& p, const std::array<double, 4>& w) {
  mpq_class m[3][4];
  for (int i = 0; i < 3; ++i) {
    mpq_class rhs = mpq_class(-w[i + 1]) + mpq_class(w[0]);
    for (std::size_t k = 0; k < 3; ++k) {
      const mpq_class a(p[0][k]);
      const mpq_class b(p[i + 1][k]);
      m[i][k] = 2 * (b - a);
      rhs += b * b - a * a;
    }
    m[i][3] = rhs;
  }
  for (int col = 0; col < 3; ++col) {
    int pivot = col;
    while (sgn(m[pivot][col]) == 0) ++pivot;
    for (int k = 0; k < 4; ++k) std::swap(m[col][k], m[pivot][k]);
    for (int row = 0; row < 3; ++row) {
      if (row == col || sgn(m[row][col]) == 0) continue;
      const mpq_class f = m[row][col] / m[col][col];
      for (int k = col; k < 4; ++k) m[row][k] -= f * m[col][k];
    }
  }
  return {mpq_class(m[0][3] / m[0][0]).get_d(), mpq_class(m[1][3] / m[1][1]).get_d(),
          mpq_class(m[2][3] / m[2][2]).get_d()};
}

}  // namespace

TEST_CASE("circum- and orthocentres of slivers: close to the exact centre") {
  // Integer points on the sphere of radius 5, moved by ~1e-9: nearly cospherical, so the
  // Delaunay cells are slivers whose centres are ill-conditioned in double arithmetic.
  std::vector<Point3> points;
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> jitter(-1e-9, 1e-9);
  for (int x = -5; x <= 5; ++x) {
    for (int y = -5; y <= 5; ++y) {
      for (int z = -5; z <= 5; ++z) {
        if (x * x + y * y + z * z != 25) continue;
        points.push_back({x + jitter(random), y + jitter(random), z + jitter(random)});
      }
    }
  }
  std::vector<double> weights(points.size());
  for (double& w : weights) w = 1e-9 * jitter(random);
  for (const bool weighted : {false, true}) {
    const RegularTriangulation3 t =
        weighted ? RegularTriangulation3(points, weights) : RegularTriangulation3(points);
    std::size_t slivers = 0;
    t.for_each_finite_cell([&](CellId c) {
      std::array<Point3, 4> p;
      std::array<double, 4> w{};
      const auto vs = t.vertices(c);
      for (int i = 0; i < 4; ++i) {
        p[i] = t.point(vs[i]);
        if (weighted) w[i] = t.weight(vs[i]);
      }
      const Point3 exact = exact_orthocenter(p, w);
      const Point3 got = weighted ? t.orthocenter(c) : t.circumcenter(c);
      const double radius = distance(exact, p[0]);
      const double volume = std::fabs(dot(p[1] - p[0], cross(p[2] - p[0], p[3] - p[0])));
      slivers += volume < 1e-6;
      // Well-shaped cells: double arithmetic, error a small multiple of 2^-27 of the
      // radius; slivers: exact, rounded once. 2^-20 of the radius covers both.
      INFO("cell volume " << volume << ", radius " << radius);
      CHECK(distance(got, exact) <= 0x1p-20 * radius);
    });
    CHECK(slivers > 0);  // the input does exercise the exact path
  }
}

TEST_CASE("bad input throws InvalidInput with a clear message") {
  using rstruct::InvalidInput;
  const auto message = [](auto&& make) {
    try {
      make();
    } catch (const InvalidInput& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  CHECK(message([] { RegularTriangulation3(std::vector<Point3>{}); }).find("fewer than 4") !=
        std::string::npos);
  CHECK(message([] { RegularTriangulation3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}); })
            .find("fewer than 4") != std::string::npos);
  CHECK(message([] {
          RegularTriangulation3({{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}});
        }).find("all equal") != std::string::npos);
  CHECK(message([] {
          RegularTriangulation3({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}, {-1, -1, -1}});
        }).find("collinear") != std::string::npos);
  CHECK(message([] { RegularTriangulation3(rstruct::test::grid_points(5, 5, 1)); })
            .find("coplanar") != std::string::npos);
  CHECK(message([] {
          RegularTriangulation3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, NAN}});
        }).find("point 3") != std::string::npos);
  CHECK(message([] {
          RegularTriangulation3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                                std::vector<double>{0.0, 1.0});
        }).find("weights") != std::string::npos);
  CHECK(message([] {
          RegularTriangulation3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                                std::vector<double>{0.0, 1.0, INFINITY, 0.0});
        }).find("weight of point 2") != std::string::npos);
}
