#pragma once
/// \file
/// Generators of deliberately degenerate inputs, for every module's tests: exactly
/// cospherical integer points, integer grids, coplanar, collinear and coincident sets,
/// perturbations by a number of ulps, scalings by powers of two into tiny and huge
/// exponents, subnormals. Everything is exact (built from small integers and powers of
/// two) unless the name says "perturb".

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "rstruct/geometry/vec3.hpp"

namespace rstruct::testing {

/// All integer points (x, y, z) with x² + y² + z² = radius2, e.g. radius2 = 4225 = 65²
/// (a radius with many representations).
inline std::vector<Point3> integer_sphere_points(std::int64_t radius2) {
  std::vector<Point3> out;
  const auto r = static_cast<std::int64_t>(std::sqrt(static_cast<double>(radius2))) + 1;
  for (std::int64_t x = -r; x <= r; ++x) {
    for (std::int64_t y = -r; y <= r; ++y) {
      const std::int64_t rest = radius2 - x * x - y * y;
      if (rest < 0) continue;
      const auto z = static_cast<std::int64_t>(std::llround(std::sqrt(static_cast<double>(rest))));
      if (z * z != rest) continue;
      out.push_back({static_cast<double>(x), static_cast<double>(y), static_cast<double>(z)});
      if (z != 0) {
        out.push_back({static_cast<double>(x), static_cast<double>(y), static_cast<double>(-z)});
      }
    }
  }
  return out;
}

/// The integer grid {0..n−1}³ scaled by `step` (exact for power-of-two steps).
inline std::vector<Point3> integer_grid(int n, double step = 1.0) {
  std::vector<Point3> out;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) out.push_back({i * step, j * step, k * step});
    }
  }
  return out;
}

/// Points o + i·u + j·v for small integers i, j drawn at random: exactly coplanar when
/// o, u, v have small integer coordinates.
template <class Rng>
std::vector<Point3> coplanar_points(Rng& rng, int count, const Point3& o, const Vec3& u,
                                    const Vec3& v, int range = 50) {
  std::uniform_int_distribution<int> d(-range, range);
  std::vector<Point3> out;
  for (int n = 0; n < count; ++n) out.push_back(o + d(rng) * u + d(rng) * v);
  return out;
}

/// Points o + i·u for small integers i: exactly collinear for integer o, u.
template <class Rng>
std::vector<Point3> collinear_points(Rng& rng, int count, const Point3& o, const Vec3& u,
                                     int range = 50) {
  std::uniform_int_distribution<int> d(-range, range);
  std::vector<Point3> out;
  for (int n = 0; n < count; ++n) out.push_back(o + d(rng) * u);
  return out;
}

/// x moved by `ulps` units in the last place away from zero (negative: towards zero),
/// crossing binades as the bit pattern does; stays finite.
inline double perturb_ulps(double x, std::int64_t ulps) {
  if (x == 0) return std::ldexp(static_cast<double>(ulps), -1074);
  const auto bits = std::bit_cast<std::int64_t>(std::fabs(x));
  std::int64_t moved = bits + ulps;
  const auto max_finite = std::bit_cast<std::int64_t>(1.7976931348623157e308);
  if (moved > max_finite) moved = max_finite;
  if (moved < 0) moved = 0;
  const double m = std::bit_cast<double>(moved);
  return x < 0 ? -m : m;
}

/// Every coordinate moved by a random number of ulps in [−max_ulps, max_ulps].
template <class Rng>
Point3 perturb_point(Rng& rng, const Point3& p, std::int64_t max_ulps) {
  std::uniform_int_distribution<std::int64_t> d(-max_ulps, max_ulps);
  return {perturb_ulps(p.x, d(rng)), perturb_ulps(p.y, d(rng)), perturb_ulps(p.z, d(rng))};
}

/// p·2^k, exact unless it leaves the normal range.
inline Point3 scale_pow2(const Point3& p, int k) {
  return {std::ldexp(p.x, k), std::ldexp(p.y, k), std::ldexp(p.z, k)};
}

/// A double with a random sign, a uniformly random exponent in [min_exp, max_exp] and a
/// random 53-bit mantissa (covers 1e-150..1e150 with min_exp = -500, max_exp = 500).
template <class Rng>
double random_magnitude(Rng& rng, int min_exp, int max_exp) {
  std::uniform_int_distribution<int> e(min_exp, max_exp);
  std::uniform_real_distribution<double> m(0.5, 1.0);
  const double v = std::ldexp(m(rng), e(rng));
  return (rng() & 1) != 0 ? -v : v;
}

/// A random subnormal double (magnitude below 2^-1022), with random sign.
template <class Rng>
double random_subnormal(Rng& rng) {
  std::uniform_int_distribution<std::uint64_t> m(1, (std::uint64_t{1} << 52) - 1);
  const double v = std::bit_cast<double>(m(rng));
  return (rng() & 1) != 0 ? -v : v;
}

/// A uniformly random point in the cube [lo, hi]³.
template <class Rng>
Point3 random_point(Rng& rng, double lo = -1.0, double hi = 1.0) {
  std::uniform_real_distribution<double> d(lo, hi);
  return {d(rng), d(rng), d(rng)};
}

}  // namespace rstruct::testing
