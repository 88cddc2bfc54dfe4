// Implicit functions, gradients, closest points and parametrizations of every surface.
#include <catch2/catch.hpp>
#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "rstruct/core/error.hpp"
#include "rstruct/sampling/double_torus.hpp"
#include "rstruct/sampling/ellipsoid.hpp"
#include "rstruct/sampling/random.hpp"
#include "rstruct/sampling/sphere.hpp"
#include "rstruct/sampling/torus.hpp"
#include "rstruct/sampling/uniform_sampling.hpp"

using namespace rstruct;
using namespace rstruct::sampling;

namespace {

std::vector<std::shared_ptr<const Surface>> parametrized_surfaces() {
  return {std::make_shared<Sphere>(1.0),        std::make_shared<Sphere>(0.25),
          std::make_shared<Ellipsoid>(3, 2, 1), std::make_shared<Ellipsoid>(1, 3, 2),
          std::make_shared<Ellipsoid>(2, 1, 1), std::make_shared<Ellipsoid>(1.5, 1.5, 1),
          std::make_shared<Torus>(3.0, 1.0),    std::make_shared<Torus>(1.5, 1.0)};
}

Point3 random_point_near(const Surface& s, Random& random) {
  const Box3 box = s.bounding_box();
  const Vec3 e = box.extent();
  return {random.uniform(box.lo.x - 0.3 * e.x, box.hi.x + 0.3 * e.x),
          random.uniform(box.lo.y - 0.3 * e.y, box.hi.y + 0.3 * e.y),
          random.uniform(box.lo.z - 0.3 * e.z, box.hi.z + 0.3 * e.z)};
}

}  // namespace

TEST_CASE("constructors reject invalid shapes") {
  CHECK_THROWS_AS(Sphere(0.0), InvalidInput);
  CHECK_THROWS_AS(Sphere(NAN), InvalidInput);
  CHECK_THROWS_AS(Ellipsoid(1, -1, 1), InvalidInput);
  CHECK_THROWS_AS(Ellipsoid(1, INFINITY, 1), InvalidInput);
  CHECK_THROWS_AS(Torus(1.0, 1.0), InvalidInput);
  CHECK_THROWS_AS(Torus(1.0, 0.0), InvalidInput);
  DoubleTorusParameters p;
  p.blend = 0.0;
  CHECK_THROWS_AS(DoubleTorus(p), InvalidInput);
  CHECK_THROWS_AS(DoubleTorus().lfs({0, 0, 0}), InvalidInput);
  CHECK_THROWS_AS(DoubleTorus().point(0, 0, 0), InvalidInput);
}

TEST_CASE("gradients match central differences") {
  Random random(7);
  auto surfaces = parametrized_surfaces();
  surfaces.push_back(std::make_shared<DoubleTorus>());
  for (const auto& s : surfaces) {
    for (int i = 0; i < 200; ++i) {
      const Point3 x = random_point_near(*s, random);
      const Vec3 g = s->gradient(x);
      const double h = 1e-6;
      for (std::size_t c = 0; c < 3; ++c) {
        Point3 a = x, b = x;
        a[c] += h;
        b[c] -= h;
        const double fd = (s->value(a) - s->value(b)) / (2 * h);
        REQUIRE(std::fabs(fd - g[c]) <= 1e-6 * (1.0 + std::fabs(g[c])));
      }
    }
  }
}

TEST_CASE("closest points lie on F and beat brute force") {
  Random random(11);
  auto surfaces = parametrized_surfaces();
  surfaces.push_back(std::make_shared<DoubleTorus>());
  for (const auto& s : surfaces) {
    INFO(s->name());
    const std::vector<Point3> dense = sample_uniform(*s, 20000, 5);
    for (int i = 0; i < 60; ++i) {
      // Queries within a moderate distance of F, where the closest point is unique.
      const Point3 y = dense[random.below(dense.size())] + random.unit_vector() * 0.1;
      const Point3 x = s->closest_point(y);
      REQUIRE(std::fabs(s->value(x)) <= 1e-12);
      const double d = distance(x, y);
      double brute = HUGE_VAL;
      for (const Point3& p : dense) brute = std::min(brute, distance(p, y));
      REQUIRE(d <= brute + 1e-12);
      // First-order optimality: y − x is normal to F at x.
      const Vec3 n = s->normal(x);
      REQUIRE(norm(cross(y - x, n)) <= 1e-10 * (1.0 + d));
    }
  }
}

TEST_CASE("charts: points on F, area elements and cell reaches") {
  Random random(3);
  for (const auto& s : parametrized_surfaces()) {
    INFO(s->name());
    double area = 0.0;
    for (int chart = 0; chart < s->chart_count(); ++chart) {
      const ParamCell d = s->chart_domain(chart);
      // Midpoint rule for the area.
      const int n = 400;
      const double du = (d.u1 - d.u0) / n, dv = (d.v1 - d.v0) / n;
      for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
          area += s->area_element(chart, d.u0 + (i + 0.5) * du, d.v0 + (j + 0.5) * dv) * du * dv;
        }
      }
      for (int k = 0; k < 300; ++k) {
        const double u = random.uniform(d.u0, d.u1), v = random.uniform(d.v0, d.v1);
        const Point3 p = s->point(chart, u, v);
        REQUIRE(std::fabs(s->value(p)) <= 1e-14);
        // |P_u × P_v| by central differences.
        const double h = 1e-6;
        const Vec3 pu = (s->point(chart, u + h, v) - s->point(chart, u - h, v)) / (2 * h);
        const Vec3 pv = (s->point(chart, u, v + h) - s->point(chart, u, v - h)) / (2 * h);
        const double fd = norm(cross(pu, pv));
        REQUIRE(std::fabs(fd - s->area_element(chart, u, v)) <= 1e-6 * (1.0 + fd));
        REQUIRE(s->area_element(chart, u, v) <= s->max_area_element(chart));
        // A random cell containing (u, v): every point of the cell within its reach.
        const double w = std::pow(2.0, -random.uniform(1, 8));
        ParamCell cell{chart, std::max(d.u0, u - w * random.uniform01()), 0, 0, 0};
        cell.u1 = std::min(d.u1, cell.u0 + w);
        cell.v0 = std::max(d.v0, v - w * random.uniform01());
        cell.v1 = std::min(d.v1, cell.v0 + w);
        const double reach = s->cell_reach(cell).radius();
        const Point3 centre = s->point(chart, cell.u_mid(), cell.v_mid());
        for (int t = 0; t < 20; ++t) {
          const Point3 q =
              s->point(chart, random.uniform(cell.u0, cell.u1), random.uniform(cell.v0, cell.v1));
          REQUIRE(distance(q, centre) <= reach);
        }
        // Corners are where the bound is tightest.
        for (double cu : {cell.u0, cell.u1}) {
          for (double cv : {cell.v0, cell.v1}) {
            REQUIRE(distance(s->point(chart, cu, cv), centre) <= reach);
          }
        }
      }
    }
    CHECK(area == Approx(s->area()).epsilon(1e-4));
  }
}

TEST_CASE("ellipsoid area formula against known values") {
  CHECK(Ellipsoid(1, 1, 1).area() == Approx(4 * std::numbers::pi).epsilon(1e-14));
  // Oblate and prolate spheroids have closed forms.
  const double a = 2.0, c = 1.0;
  const double e = std::sqrt(1 - c * c / (a * a));
  const double oblate = 2 * std::numbers::pi * a * a * (1 + (1 - e * e) / e * std::atanh(e));
  CHECK(Ellipsoid(a, a, c).area() == Approx(oblate).epsilon(1e-12));
  const double prolate = 2 * std::numbers::pi * c * c * (1 + a / (c * e) * std::asin(e));
  CHECK(Ellipsoid(a, c, c).area() == Approx(prolate).epsilon(1e-12));
}

TEST_CASE("is_inside agrees with the implicit function and the geometry") {
  Sphere sphere(2.0);
  CHECK(sphere.is_inside({1.9, 0, 0}));
  CHECK_FALSE(sphere.is_inside({2.1, 0, 0}));
  Torus torus(3.0, 1.0);
  CHECK(torus.is_inside({3.0, 0, 0.5}));
  CHECK_FALSE(torus.is_inside({0, 0, 0}));
  DoubleTorus dt;
  CHECK(dt.is_inside({1.0, 0, 0}));         // big tube
  CHECK(dt.is_inside({1.7 + 0.45, 0, 0}));  // small tube, far side
  CHECK_FALSE(dt.is_inside({0, 0, 0}));     // big hole
  CHECK_FALSE(dt.is_inside({1.7, 0, 0}));   // small hole
  CHECK(dt.bounding_box().hi.x > 1.7 + 0.45 + 0.18);
}

TEST_CASE("sizes outside the supported range are rejected, not mishandled") {
  CHECK_THROWS_AS(Sphere(1e300), InvalidInput);
  CHECK_THROWS_AS(Sphere(1e-300), InvalidInput);
  CHECK_THROWS_AS(Ellipsoid(1e100, 1, 1), InvalidInput);
  CHECK_THROWS_AS(Torus(1e95, 1.0), InvalidInput);
  DoubleTorusParameters p;
  p.small_centre_x = 1e300;
  CHECK_THROWS_AS(DoubleTorus(p), InvalidInput);
  // The extremes of the range still work.
  CHECK(sample_uniform(Sphere(1e90), 10, 1).size() == 10);
  CHECK(sample_uniform(Sphere(1e-90), 10, 1).size() == 10);
}
