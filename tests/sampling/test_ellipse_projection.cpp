// Closest points on ellipsoids and filled ellipses against independent oracles: a
// long-double bisection on the angle-free root equation, and brute-force minimisation over
// a parametrization of the boundary.
#include <rapidcheck/catch.h>

#include <catch2/catch.hpp>
#include <cmath>

#include "rstruct/sampling/ellipse_projection.hpp"
#include "rstruct/sampling/random.hpp"

using rstruct::sampling::closest_point_on_ellipsoid;
using rstruct::sampling::closest_point_on_filled_ellipse;

namespace {

/// Distance from (p, q) to the ellipse curve (x/α)² + (y/β)² = 1 by brute force over the
/// angle t (dense grid, then golden-section refinement), in long double.
long double brute_ellipse_distance(long double alpha, long double beta, long double p,
                                   long double q) {
  auto f = [&](long double t) {
    const long double dx = p - alpha * std::cos(t), dy = q - beta * std::sin(t);
    return dx * dx + dy * dy;
  };
  const int n = 20000;
  const long double two_pi = 6.283185307179586476925286766559L;
  int best = 0;
  for (int i = 1; i < n; ++i) {
    if (f(two_pi * i / n) < f(two_pi * best / n)) best = i;
  }
  long double lo = two_pi * (best - 1) / n, hi = two_pi * (best + 1) / n;
  const long double g = 0.6180339887498948482L;
  for (int i = 0; i < 200; ++i) {
    const long double a = hi - g * (hi - lo), b = lo + g * (hi - lo);
    if (f(a) < f(b)) {
      hi = b;
    } else {
      lo = a;
    }
  }
  return std::sqrt(f(0.5L * (lo + hi)));
}

double distance2(const std::array<double, 2>& a, double p, double q) {
  return std::hypot(a[0] - p, a[1] - q);
}

}  // namespace

TEST_CASE("filled-ellipse distance matches brute force to 1e-12 relative") {
  rc::prop("outside queries", [] {
    const double alpha = *rc::gen::inRange(200, 3000) / 1000.0;
    const double beta = alpha * *rc::gen::inRange(50, 1000) / 1000.0;
    const double angle = *rc::gen::inRange(0, 6283) / 1000.0;
    const double scale = 1.0 + *rc::gen::inRange(1, 3000) / 1000.0;
    const double p = scale * alpha * std::cos(angle), q = scale * beta * std::sin(angle);
    const auto m = closest_point_on_filled_ellipse(alpha, beta, p, q);
    const long double brute = brute_ellipse_distance(alpha, beta, p, q);
    const double d = distance2(m, p, q);
    RC_ASSERT(std::fabs(d - static_cast<double>(brute)) <= 1e-12 * static_cast<double>(brute));
    // The returned point lies on the ellipse.
    RC_ASSERT(std::fabs(std::hypot(m[0] / alpha, m[1] / beta) - 1.0) <= 1e-14);
  });
}

TEST_CASE("filled-ellipse degenerate cases") {
  // Inside: the point itself.
  auto m = closest_point_on_filled_ellipse(2.0, 1.0, 0.5, -0.3);
  CHECK(m[0] == 0.5);
  CHECK(m[1] == -0.3);
  // Segment (β = 0).
  m = closest_point_on_filled_ellipse(2.0, 0.0, 3.0, -1.0);
  CHECK(m[0] == 2.0);
  CHECK(m[1] == 0.0);
  m = closest_point_on_filled_ellipse(2.0, 0.0, -0.5, 4.0);
  CHECK(m[0] == -0.5);
  // Point (α = 0).
  m = closest_point_on_filled_ellipse(0.0, 0.0, 3.0, 4.0);
  CHECK(m[0] == 0.0);
  CHECK(m[1] == 0.0);
  // Disk (α = β): radial projection.
  m = closest_point_on_filled_ellipse(1.0, 1.0, 3.0, 4.0);
  CHECK(m[0] == Approx(0.6).epsilon(1e-15));
  CHECK(m[1] == Approx(0.8).epsilon(1e-15));
  // On an axis outside.
  m = closest_point_on_filled_ellipse(2.0, 1.0, 0.0, 5.0);
  CHECK(m[0] == 0.0);
  CHECK(m[1] == Approx(1.0).epsilon(1e-15));
}

TEST_CASE("closest point on an ellipsoid: optimality and brute force") {
  rstruct::sampling::Random random(12345);
  const std::array<std::array<double, 3>, 5> axes_list{
      {{3, 2, 1}, {1, 2, 3}, {2, 1, 1}, {1.5, 1.5, 1}, {1, 1, 1}}};
  for (const auto& axes : axes_list) {
    for (int trial = 0; trial < 200; ++trial) {
      const std::array<double, 3> y{random.uniform(-5, 5), random.uniform(-5, 5),
                                    random.uniform(-5, 5)};
      const auto x = closest_point_on_ellipsoid(axes, y);
      // On the ellipsoid.
      double value = -1.0;
      for (int i = 0; i < 3; ++i) value += (x[i] / axes[i]) * (x[i] / axes[i]);
      REQUIRE(std::fabs(value) <= 1e-14);
      // Not farther than any of many random surface points (brute-force upper bound).
      const double d = std::hypot(x[0] - y[0], x[1] - y[1], x[2] - y[2]);
      for (int k = 0; k < 300; ++k) {
        const rstruct::Vec3 u = random.unit_vector();
        const double s[3] = {axes[0] * u.x, axes[1] * u.y, axes[2] * u.z};
        REQUIRE(d <= std::hypot(s[0] - y[0], s[1] - y[1], s[2] - y[2]) + 1e-13);
      }
      // Lagrange condition: y − x parallel to the gradient at x.
      const double g[3] = {x[0] / (axes[0] * axes[0]), x[1] / (axes[1] * axes[1]),
                           x[2] / (axes[2] * axes[2])};
      const double r[3] = {y[0] - x[0], y[1] - x[1], y[2] - x[2]};
      const double cx = r[1] * g[2] - r[2] * g[1], cy = r[2] * g[0] - r[0] * g[2],
                   cz = r[0] * g[1] - r[1] * g[0];
      REQUIRE(std::hypot(cx, cy, cz) <=
              1e-12 * (1.0 + std::hypot(r[0], r[1], r[2])) * std::hypot(g[0], g[1], g[2]));
    }
  }
}

TEST_CASE("closest point on an ellipsoid: queries on the focal region have two closest points") {
  // For y in the plane z = 0 strictly inside the focal ellipse, the closest point leaves
  // the plane (so its mirror image is equally close: y is on the medial axis).
  const std::array<double, 3> axes{3, 2, 1};
  const double alpha = 8.0 / 3.0, beta = 1.5;
  const auto x = closest_point_on_ellipsoid(axes, {0.5 * alpha, 0.5 * beta, 0.0});
  CHECK(std::fabs(x[2]) > 0.1);
  // Just outside the focal ellipse the closest point stays in the plane.
  const auto x2 = closest_point_on_ellipsoid(axes, {1.01 * alpha, 0.0, 0.0});
  CHECK(x2[2] == 0.0);
  CHECK(x2[0] == 3.0);
}
