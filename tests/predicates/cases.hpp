#pragma once
// Input families for the predicate tests: uniform random, exactly degenerate (grid,
// cospherical, coplanar, collinear, coincident, orthogonal weights), their perturbations
// by 1 to 2^50 ulps, magnitudes from 1e-150 to 1e150, mixed magnitudes and subnormals.

#include <array>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "support/degenerate.hpp"

namespace rstruct::testing {

enum class Family {
  uniform,
  grid,
  cospherical,
  coplanar,
  collinear,
  coincident,
  perturbed,
  scaled,
  mixed_magnitudes,
  subnormal,
  count_
};

inline const char* family_name(Family f) {
  static const char* names[] = {"uniform", "grid", "cospherical", "coplanar", "collinear",
                                "coincident", "perturbed", "scaled", "mixed_magnitudes",
                                "subnormal"};
  return names[static_cast<int>(f)];
}

inline const std::vector<Point3>& sphere_65() {
  static const std::vector<Point3> pts = integer_sphere_points(4225);
  return pts;
}

template <std::size_t N, class Rng>
std::array<Point3, N> exactly_degenerate(Rng& rng) {
  std::uniform_int_distribution<int> small(-20, 20), kind(0, 4);
  const Vec3 o{double(small(rng)), double(small(rng)), double(small(rng))};
  std::array<Point3, N> p;
  switch (kind(rng)) {
    case 0: {  // cospherical
      std::uniform_int_distribution<std::size_t> pick(0, sphere_65().size() - 1);
      for (auto& q : p) q = sphere_65()[pick(rng)] + o;
      break;
    }
    case 1: {  // coplanar
      const Vec3 u{double(small(rng)), double(small(rng)), double(small(rng))};
      const Vec3 v{double(small(rng)), double(small(rng)), double(small(rng))};
      const auto pts = coplanar_points(rng, int(N), o, u, v, 10);
      for (std::size_t i = 0; i < N; ++i) p[i] = pts[i];
      break;
    }
    case 2: {  // collinear
      const Vec3 u{double(small(rng)), double(small(rng)), double(small(rng))};
      const auto pts = collinear_points(rng, int(N), o, u, 10);
      for (std::size_t i = 0; i < N; ++i) p[i] = pts[i];
      break;
    }
    case 3: {  // grid
      std::uniform_int_distribution<int> g(0, 2);
      for (auto& q : p) q = Point3{double(g(rng)), double(g(rng)), double(g(rng))} + o;
      break;
    }
    default: {  // coincident pairs among random small integers
      for (auto& q : p) q = Point3{double(small(rng)), double(small(rng)), double(small(rng))};
      std::uniform_int_distribution<std::size_t> i(0, N - 1);
      p[i(rng)] = p[i(rng)];
      break;
    }
  }
  return p;
}

/// N points of the given family.
template <std::size_t N, class Rng>
std::array<Point3, N> make_points(Rng& rng, Family f) {
  std::array<Point3, N> p;
  switch (f) {
    case Family::uniform:
      for (auto& q : p) q = random_point(rng);
      return p;
    case Family::grid: {
      std::uniform_int_distribution<int> g(0, 3);
      for (auto& q : p) q = {double(g(rng)), double(g(rng)), double(g(rng))};
      return p;
    }
    case Family::cospherical: {
      std::uniform_int_distribution<std::size_t> pick(0, sphere_65().size() - 1);
      for (auto& q : p) q = sphere_65()[pick(rng)];
      return p;
    }
    case Family::coplanar: {
      const auto pts = coplanar_points(rng, int(N), {3, -1, 2}, {1, 2, -1}, {-2, 1, 3});
      for (std::size_t i = 0; i < N; ++i) p[i] = pts[i];
      return p;
    }
    case Family::collinear: {
      const auto pts = collinear_points(rng, int(N), {3, -1, 2}, {1, 2, -1});
      for (std::size_t i = 0; i < N; ++i) p[i] = pts[i];
      return p;
    }
    case Family::coincident: {
      for (auto& q : p) q = random_point(rng);
      std::uniform_int_distribution<std::size_t> i(0, N - 1);
      p[i(rng)] = p[i(rng)];
      p[i(rng)] = p[i(rng)];
      return p;
    }
    case Family::perturbed: {
      p = exactly_degenerate<N>(rng);
      std::uniform_int_distribution<int> bits(0, 50);
      const std::int64_t max_ulps = std::int64_t{1} << bits(rng);
      std::uniform_int_distribution<std::size_t> which(0, N - 1);
      // Perturb one point (sometimes all): the configuration stays nearly degenerate.
      if (rng() % 2 == 0) {
        const std::size_t k = which(rng);
        p[k] = perturb_point(rng, p[k], max_ulps);
      } else {
        for (auto& q : p) q = perturb_point(rng, q, max_ulps);
      }
      return p;
    }
    case Family::scaled: {
      p = (rng() % 2 == 0) ? exactly_degenerate<N>(rng) : make_points<N>(rng, Family::uniform);
      std::uniform_int_distribution<int> k(-500, 500);
      const int e = k(rng);
      for (auto& q : p) q = scale_pow2(q, e);
      if (rng() % 2 == 0) p[0] = perturb_point(rng, p[0], 3);
      return p;
    }
    case Family::mixed_magnitudes:
      for (auto& q : p) {
        q = {random_magnitude(rng, -500, 500), random_magnitude(rng, -500, 500),
             random_magnitude(rng, -500, 500)};
      }
      return p;
    case Family::subnormal:
      for (auto& q : p) {
        q = {random_subnormal(rng), random_subnormal(rng), random_subnormal(rng)};
        if (rng() % 3 == 0) q.x = random_magnitude(rng, -1074, -1000);
        if (rng() % 4 == 0) q.y = 0;
      }
      return p;
    case Family::count_:
      break;
  }
  return p;
}

/// Weights for N points: zero, random, equal, or orthogonal to one exactly
/// representable sphere (then every power test is exactly zero), sometimes perturbed.
template <std::size_t N, class Rng>
std::array<WeightedPoint, N> make_weighted(Rng& rng, Family f) {
  const std::array<Point3, N> p = make_points<N>(rng, f);
  std::array<WeightedPoint, N> out;
  std::uniform_int_distribution<int> kind(0, 3), small(-8, 8);
  const int k = kind(rng);
  const Point3 z{double(small(rng)), double(small(rng)), double(small(rng))};
  const double big_w = double(small(rng));
  std::uniform_real_distribution<double> w(-1.0, 1.0);
  for (std::size_t i = 0; i < N; ++i) {
    out[i].c = p[i];
    switch (k) {
      case 0: out[i].w = 0; break;
      case 1: out[i].w = w(rng) * squared_norm(p[i] - p[0]); break;
      case 2: out[i].w = 0.25; break;
      default:
        // Orthogonal to (z, big_w): |p − z|² − w = big_w, exact for integer-valued data.
        out[i].w = squared_distance(p[i], z) - big_w;
        if (rng() % 4 == 0) out[i].w = perturb_ulps(out[i].w, 1);
        break;
    }
  }
  return out;
}

}  // namespace rstruct::testing
