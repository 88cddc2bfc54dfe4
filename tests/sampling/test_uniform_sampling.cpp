// Uniform-by-area sampling of surfaces and triangle meshes: on the surface, deterministic
// for a seed, and with region frequencies matching area fractions (binomial tolerances of
// five standard deviations).
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "rstruct/core/error.hpp"
#include "rstruct/sampling/double_torus.hpp"
#include "rstruct/sampling/ellipsoid.hpp"
#include "rstruct/sampling/implicit_mesher.hpp"
#include "rstruct/sampling/sphere.hpp"
#include "rstruct/sampling/torus.hpp"
#include "rstruct/sampling/uniform_sampling.hpp"

using namespace rstruct;
using namespace rstruct::sampling;

namespace {

/// |observed fraction − p| within five binomial standard deviations.
bool fraction_matches(std::size_t hits, std::size_t n, double p) {
  const double f = static_cast<double>(hits) / static_cast<double>(n);
  return std::fabs(f - p) <= 5.0 * std::sqrt(p * (1 - p) / static_cast<double>(n));
}

}  // namespace

TEST_CASE("sphere: points on the sphere, caps get their area fraction") {
  Sphere s(2.0);
  const auto pts = sample_uniform(s, 40000, 1);
  REQUIRE(pts.size() == 40000);
  std::size_t cap = 0;
  for (const Point3& p : pts) {
    REQUIRE(std::fabs(norm(p) - 2.0) <= 1e-14);
    if (p.z > 1.0) ++cap;  // cap of height 1 on a sphere of radius 2: fraction 1/4
  }
  CHECK(fraction_matches(cap, pts.size(), 0.25));
}

TEST_CASE("torus: the outer half (cos phi > 0) gets its area fraction") {
  const double R = 3.0, a = 1.0;
  Torus t(R, a);
  const auto pts = sample_uniform(t, 40000, 2);
  std::size_t outer = 0;
  for (const Point3& p : pts) {
    REQUIRE(std::fabs(t.value(p)) <= 1e-14);
    if (std::hypot(p.x, p.y) > R) ++outer;
  }
  CHECK(fraction_matches(outer, pts.size(),
                         (std::numbers::pi * R + 2 * a) / (2 * std::numbers::pi * R)));
}

TEST_CASE("ellipsoid: a band gets its area fraction") {
  Ellipsoid e(3, 2, 1);
  // Area of the band |z| < 0.5 by the midpoint rule on the charts (independent of the
  // rejection sampler).
  double band = 0.0, total = 0.0;
  for (int chart = 0; chart < 6; ++chart) {
    const int n = 300;
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        const double u = -1 + (i + 0.5) * 2.0 / n, v = -1 + (j + 0.5) * 2.0 / n;
        const double w = e.area_element(chart, u, v) * (4.0 / (n * n));
        total += w;
        if (std::fabs(e.point(chart, u, v).z) < 0.5) band += w;
      }
    }
  }
  const auto pts = sample_uniform(e, 40000, 3);
  std::size_t hits = 0;
  for (const Point3& p : pts) hits += std::fabs(p.z) < 0.5;
  CHECK(fraction_matches(hits, pts.size(), band / total));
}

TEST_CASE("sampling is deterministic for a seed") {
  Torus t(3.0, 1.0);
  CHECK(sample_uniform(t, 100, 42) == sample_uniform(t, 100, 42));
  CHECK(sample_uniform(t, 100, 42) != sample_uniform(t, 100, 43));
  CHECK(sample_uniform(t, 0, 42).empty());
}

TEST_CASE("double torus: the paper's 85237 points, on F, spread by area") {
  DoubleTorus dt;
  const auto pts = sample_uniform(dt, 85237, 2009);
  REQUIRE(pts.size() == 85237);
  std::size_t small_ring = 0;
  for (const Point3& p : pts) {
    REQUIRE(std::fabs(dt.value(p)) <= 1e-12);
    if (p.x > 1.45) ++small_ring;
  }
  // Area fraction of {x > 1.45} from an independent, finer mesh (triangle centroids).
  const TriangleMesh mesh = mesh_implicit_surface(dt, 0.02, true);
  double part = 0.0, total = 0.0;
  for (const auto& f : mesh.faces) {
    const Point3 &a = mesh.vertices[f[0]], &b = mesh.vertices[f[1]], &c = mesh.vertices[f[2]];
    const double area = 0.5 * norm(cross(b - a, c - a));
    total += area;
    if ((a.x + b.x + c.x) / 3.0 > 1.45) part += area;
  }
  CHECK(fraction_matches(small_ring, pts.size(), part / total));
}

TEST_CASE("mesh sampling: area-weighted triangles, uniform inside, validated input") {
  TriangleMesh m;
  // Two triangles of areas 1/2 and 3/2 in the plane z = 0, and one degenerate triangle.
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {3, 0, 0}, {3, 1, 0}, {6, 0, 0}, {7, 0, 0}};
  m.faces = {{0, 1, 2}, {3, 5, 4}, {5, 6, 5}};
  const auto pts = sample_mesh_uniform(m, 20000, 9);
  REQUIRE(pts.size() == 20000);
  std::size_t first = 0, lower_half = 0;
  for (const Point3& p : pts) {
    REQUIRE(p.z == 0.0);
    if (p.x <= 1.0) {
      ++first;
      REQUIRE(p.x >= 0.0);
      REQUIRE(p.y >= 0.0);
      REQUIRE(p.x + p.y <= 1.0 + 1e-15);
      lower_half += p.y < 1.0 - std::sqrt(0.5);  // the band below holds half the area
    } else {
      REQUIRE(p.x >= 3.0);
      REQUIRE(p.x <= 6.0);
    }
  }
  CHECK(fraction_matches(first, pts.size(), 0.25));
  CHECK(fraction_matches(lower_half, first, 0.5));
  CHECK(sample_mesh_uniform(m, 50, 1) == sample_mesh_uniform(m, 50, 1));

  TriangleMesh empty;
  CHECK_THROWS_AS(sample_mesh_uniform(empty, 10, 1), InvalidInput);
  TriangleMesh flat = m;
  flat.faces = {{5, 6, 5}};
  CHECK_THROWS_AS(sample_mesh_uniform(flat, 10, 1), InvalidInput);
  TriangleMesh bad = m;
  bad.faces.push_back({0, 1, 99});
  CHECK_THROWS_AS(sample_mesh_uniform(bad, 10, 1), InvalidInput);
  TriangleMesh nan = m;
  nan.vertices[0].x = NAN;
  CHECK_THROWS_AS(sample_mesh_uniform(nan, 10, 1), InvalidInput);
  CHECK_THROWS_AS(sample_mesh_uniform(m, std::size_t{2000000000}, 1), InvalidInput);
}
