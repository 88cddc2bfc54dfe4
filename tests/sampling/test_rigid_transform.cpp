// Rigid transforms and transformed surfaces: everything moves consistently, also far from
// the origin.
#include <rapidcheck/catch.h>

#include <catch2/catch.hpp>
#include <cmath>

#include "rstruct/core/error.hpp"
#include "rstruct/sampling/ellipsoid.hpp"
#include "rstruct/sampling/rigid_transform.hpp"
#include "rstruct/sampling/torus.hpp"
#include "rstruct/sampling/uniform_sampling.hpp"

using namespace rstruct;
using namespace rstruct::sampling;

namespace {

double det3(const std::array<double, 9>& q) {
  return q[0] * (q[4] * q[8] - q[5] * q[7]) - q[1] * (q[3] * q[8] - q[5] * q[6]) +
         q[2] * (q[3] * q[7] - q[4] * q[6]);
}

}  // namespace

TEST_CASE("random rotations are rotations and deterministic") {
  rc::prop("orthogonal with determinant 1", [](std::uint64_t seed) {
    Random a(seed), b(seed);
    const RigidTransform q = RigidTransform::random_rotation(a);
    const RigidTransform r = RigidTransform::random_rotation(b);
    RC_ASSERT(q.q == r.q);
    // Bounds to first order in u = 2⁻⁵³ (with room for the second). The normalised
    // quaternion q̂ has s = |q̂|² within 8u of 1 (the norm: its sum of squares 4u, halved
    // by the square root, plus the root's rounding, 3u, doubled in s; each division's
    // rounding u, doubled), and the
    // formula's exact matrix is then M = (1 − s)I + sR for a rotation R, so that
    // MᵀM − I = s(1 − s)(R + Rᵀ − 2I): entries up to 4·8u = 32u (R a half turn). The
    // computed entries differ from M's by at most 5u on the diagonal (two squares, a sum,
    // the subtraction from 1) and 2u off it, adding at most 2·√33·u ≈ 11.5u to QᵀQ, and
    // orthogonality_defect's own sums of three products add 3u: 46.5u in all. (Measured
    // over seeds 0..3·10⁶: at most 23u. An earlier bound of 20u, which left out the
    // normalisation, held for all but 4 of those seeds, and failed a run of the suite.)
    RC_ASSERT(q.orthogonality_defect() <= 48 * 0x1.0p-53);
    // det M − 1 = 2(s − 1)(cos φ − 1) to first order (φ the angle of R): up to 32u; the
    // entries' errors move det by at most ‖M‖_F‖E‖_F ≈ √3·√99·u ≈ 17.2u, and det3's own
    // roundings of terms of size ≤ 1 add at most about 10u: 59.2u. (Measured as above: 23u.)
    RC_ASSERT(std::fabs(det3(q.q) - 1.0) <= 64 * 0x1.0p-53);
    const Vec3 v{0.3, -1.2, 2.0};
    RC_ASSERT(norm(q.apply_inverse(q.apply(v)) - v) <= 1e-14);
  });
}

TEST_CASE("random rotations are spread uniformly") {
  // For Haar-distributed Q, Q e_z is uniform on the sphere: its mean is 0 and the mean of
  // z² is 1/3 (tolerances are about 5 standard deviations for 20000 draws).
  Random random(2024);
  Vec3 mean{};
  double z2 = 0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const Vec3 v = RigidTransform::random_rotation(random).rotate({0, 0, 1});
    mean += v / n;
    z2 += v.z * v.z / n;
  }
  CHECK(norm(mean) < 5 * std::sqrt(1.0 / (3.0 * n)) * std::sqrt(3.0));
  CHECK(std::fabs(z2 - 1.0 / 3.0) < 5 * std::sqrt(4.0 / 45.0 / n));
}

TEST_CASE("transformed surfaces move value, normal, closest point, lfs and medial points") {
  Random random(77);
  const auto base = std::make_shared<Ellipsoid>(3, 2, 1);
  for (double shift : {0.0, 10.0, 1e6}) {
    RigidTransform t = RigidTransform::random_rotation(random);
    t.t = {shift, -0.5 * shift, 0.25 * shift};
    TransformedSurface moved(base, t);
    const double tol = 1e-12 * (1.0 + shift);
    for (const Point3& p : sample_uniform(*base, 200, 4)) {
      const Point3 x = t.apply(p);
      REQUIRE(std::fabs(moved.value(x)) <= 1e-9 + 10 * tol);
      REQUIRE(norm(moved.normal(x) - t.rotate(base->normal(p))) <= 1e-9 + tol);
      REQUIRE(moved.lfs(x) == Approx(base->lfs(p)).margin(10 * tol));
      const Point3 m = *moved.nearest_inner_medial_point(x);
      REQUIRE(norm(m - t.apply(*base->nearest_inner_medial_point(p))) <= 10 * tol);
      const Point3 y = x + t.rotate(base->normal(p)) * 0.2;
      REQUIRE(norm(moved.closest_point(y) - x) <= 1e-9 + 10 * tol);
      // Charts move too; area elements do not change.
      REQUIRE(norm(moved.point(0, 0.1, 0.2) - t.apply(base->point(0, 0.1, 0.2))) == 0.0);
    }
    CHECK_FALSE(moved.nearest_outer_medial_point(t.t).has_value());
    CHECK(moved.area() == base->area());
    // The pad is at the level of coordinate rounding: a few ulps of |t| and the extent.
    CHECK(moved.rounding_pad() <= 0x1.0p-46 * (10.0 + 2.0 * norm(t.t)));
    const Box3 box = moved.bounding_box();
    for (const Point3& p : sample_uniform(moved, 100, 5)) {
      REQUIRE(p.x >= box.lo.x);
      REQUIRE(p.z <= box.hi.z);
    }
  }
}

TEST_CASE("torus moved: the outer medial axis is the moved symmetry axis") {
  const auto base = std::make_shared<Torus>(3.0, 1.0);
  Random random(8);
  RigidTransform t = RigidTransform::random_rotation(random);
  t.t = {1, 2, 3};
  TransformedSurface moved(base, t);
  const Point3 x = t.apply({4, 0, 0});
  const Point3 m = *moved.nearest_outer_medial_point(x);
  CHECK(norm(m - t.t) <= 1e-14 * 10);
  CHECK(moved.lfs(x) == Approx(1.0));
}

TEST_CASE("transformed surfaces reject bad transforms") {
  const auto base = std::make_shared<Torus>(3.0, 1.0);
  RigidTransform t;
  t.q[0] = 2.0;
  CHECK_THROWS_AS(TransformedSurface(base, t), InvalidInput);
  t = RigidTransform::translation({NAN, 0, 0});
  CHECK_THROWS_AS(TransformedSurface(base, t), InvalidInput);
  CHECK_THROWS_AS(TransformedSurface(nullptr, RigidTransform{}), InvalidInput);
  CHECK_THROWS_AS(RigidTransform::from_quaternion(0, 0, 0, 0), InvalidInput);
}

TEST_CASE("translations beyond 1e15 are rejected") {
  const auto base = std::make_shared<Torus>(3.0, 1.0);
  CHECK_NOTHROW(TransformedSurface(base, RigidTransform::translation({1e15, 0, 0})));
  CHECK_THROWS_AS(TransformedSurface(base, RigidTransform::translation({0, -1e16, 0})),
                  InvalidInput);
}
