// Local feature size formulas (DESIGN.md §8) against brute force: the distance to a densely
// sampled medial axis, a long-double oracle for the ellipsoid, and checks that the claimed
// medial axis really consists of centres of balls touching F twice.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <vector>

#include "rstruct/sampling/ellipsoid.hpp"
#include "rstruct/sampling/random.hpp"
#include "rstruct/sampling/sphere.hpp"
#include "rstruct/sampling/torus.hpp"
#include "rstruct/sampling/uniform_sampling.hpp"

using namespace rstruct;
using namespace rstruct::sampling;

namespace {

double brute_distance(const Point3& x, const std::vector<Point3>& set) {
  double d = HUGE_VAL;
  for (const Point3& p : set) d = std::min(d, distance(x, p));
  return d;
}

/// Points of the filled focal ellipse of an axis-aligned ellipsoid with sorted axes
/// (a, b, c) along (x, y, z): a polar grid with spacing about `h`.
std::vector<Point3> focal_region_points(double alpha, double beta, double h) {
  std::vector<Point3> pts;
  const int rings = static_cast<int>(std::ceil(1.0 / (h / alpha))) + 1;
  for (int i = 0; i <= rings; ++i) {
    const double s = static_cast<double>(i) / rings;
    const int n = std::max(8, static_cast<int>(2 * std::numbers::pi * s * alpha / h));
    for (int j = 0; j < n; ++j) {
      const double t = 2 * std::numbers::pi * j / n;
      pts.push_back({s * alpha * std::cos(t), s * beta * std::sin(t), 0.0});
    }
  }
  return pts;
}

/// Long-double distance from (p, q, z) to the filled ellipse, by bisection on the root
/// equation (an oracle with 64-bit mantissa, independent of the double code path).
long double oracle_region_distance(long double alpha, long double beta, long double p,
                                   long double q, long double z) {
  p = std::fabs(p);
  q = std::fabs(q);
  if ((p / alpha) * (p / alpha) + (q / beta) * (q / beta) <= 1) return std::fabs(z);
  auto G = [&](long double s) {
    const long double u = alpha * p / (s + alpha * alpha), w = beta * q / (s + beta * beta);
    return u * u + w * w - 1;
  };
  long double lo = 0, hi = std::hypot(alpha * p, beta * q);
  for (int i = 0; i < 200; ++i) {
    const long double mid = 0.5L * (lo + hi);
    (G(mid) > 0 ? lo : hi) = mid;
  }
  const long double s = 0.5L * (lo + hi);
  const long double x = alpha * alpha * p / (s + alpha * alpha);
  const long double y = beta * beta * q / (s + beta * beta);
  return std::sqrt((x - p) * (x - p) + (y - q) * (y - q) + z * z);
}

}  // namespace

TEST_CASE("sphere: lfs is the radius") {
  Sphere s(2.5);
  for (const Point3& p : sample_uniform(s, 200, 1)) CHECK(s.lfs(p) == Approx(2.5).epsilon(1e-15));
}

TEST_CASE("torus: lfs against the distance to a dense medial axis") {
  for (const auto& [major, minor] : {std::pair{3.0, 1.0}, std::pair{1.5, 1.0}}) {
    Torus t(major, minor);
    std::vector<Point3> medial;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
      const double a = 2 * std::numbers::pi * i / n;
      medial.push_back({major * std::cos(a), major * std::sin(a), 0.0});
      medial.push_back({0.0, 0.0, -2.0 + 4.0 * i / n});
    }
    const double spacing = 2 * std::numbers::pi * major / n;
    for (const Point3& x : sample_uniform(t, 300, 2)) {
      const double l = t.lfs(x);
      const double brute = brute_distance(x, medial);
      REQUIRE(l <= brute + 1e-12);
      REQUIRE(brute - l <= spacing);
      if (major >= 2 * minor) REQUIRE(l == Approx(minor).epsilon(1e-14));
    }
  }
}

TEST_CASE("ellipsoid: lfs against brute force and a long-double oracle") {
  const std::array<std::array<double, 3>, 3> cases{{{3, 2, 1}, {2, 1.5, 1}, {1.5, 1.2, 1}}};
  for (const auto& axes : cases) {
    Ellipsoid e(axes[0], axes[1], axes[2]);
    const double alpha = e.focal_alpha(), beta = e.focal_beta();
    CHECK(alpha == Approx((axes[0] * axes[0] - axes[2] * axes[2]) / axes[0]));
    CHECK(beta == Approx((axes[1] * axes[1] - axes[2] * axes[2]) / axes[1]));
    const double h = 0.004;
    const std::vector<Point3> medial = focal_region_points(alpha, beta, h);
    for (const Point3& x : sample_uniform(e, 200, 3)) {
      const double l = e.lfs(x);
      const double brute = brute_distance(x, medial);
      REQUIRE(l <= brute + 1e-12);
      REQUIRE(brute - l <= h);
      const long double oracle = oracle_region_distance(alpha, beta, x.x, x.y, x.z);
      REQUIRE(std::fabs(l - static_cast<double>(oracle)) <= 1e-12 * l);
    }
    // Tip of the major axis: lfs = c²/a (the smallest radius of curvature there).
    CHECK(e.lfs({axes[0], 0, 0}) == Approx(axes[2] * axes[2] / axes[0]).epsilon(1e-14));
  }
}

TEST_CASE("ellipsoid: the focal region is exactly where balls touch F twice") {
  // A point m in the plane of the two largest axes is on the medial axis iff its closest
  // point on F leaves that plane (then the mirror image is a second closest point).
  Ellipsoid e(3, 2, 1);
  Random random(5);
  for (int i = 0; i < 500; ++i) {
    const double t = random.uniform(0, 2 * std::numbers::pi);
    const double s = random.uniform(0.02, 1.3);
    const Point3 m{s * e.focal_alpha() * std::cos(t), s * e.focal_beta() * std::sin(t), 0.0};
    const Point3 x = e.closest_point(m);
    if (s < 0.98) {
      REQUIRE(std::fabs(x.z) > 1e-3);
      const Point3 mirror{x.x, x.y, -x.z};
      REQUIRE(distance(m, mirror) == Approx(distance(m, x)).epsilon(1e-14));
      // The claimed nearest medial point of m is m itself.
      REQUIRE(distance(*e.nearest_inner_medial_point(m), m) == 0.0);
    } else if (s > 1.02) {
      REQUIRE(x.z == 0.0);
    }
  }
}

TEST_CASE("ellipsoid with permuted and equal axes") {
  // Same shape, axes permuted: lfs is the same at corresponding points.
  Ellipsoid a(3, 2, 1), b(1, 3, 2);
  Random random(9);
  for (int i = 0; i < 100; ++i) {
    const Vec3 u = random.unit_vector();
    const Point3 pa{3 * u.x, 2 * u.y, 1 * u.z};
    const Point3 pb{1 * u.z, 3 * u.x, 2 * u.y};
    REQUIRE(a.lfs(pa) == Approx(b.lfs(pb)).epsilon(1e-13));
  }
  // Prolate spheroid: the medial axis is the segment |x| ≤ (a² − c²)/a on the x axis.
  Ellipsoid prolate(2, 1, 1);
  CHECK(prolate.focal_beta() == 0.0);
  CHECK(prolate.lfs({0, 1, 0}) == Approx(1.0));
  CHECK(prolate.lfs({2, 0, 0}) == Approx(0.5));
  // Oblate: a disk of radius (a² − c²)/a.
  Ellipsoid oblate(2, 2, 1);
  CHECK(oblate.lfs({0, 0, 1}) == Approx(1.0));
  CHECK(oblate.lfs({0, 2, 0}) == Approx(0.5));
  // A sphere given as an ellipsoid: lfs = radius.
  CHECK(Ellipsoid(1.5, 1.5, 1.5).lfs({0, 1.5, 0}) == Approx(1.5));
}
