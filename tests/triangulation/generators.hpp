#pragma once
// Point-set generators for the triangulation tests: degenerate on purpose (integer grids,
// exactly cospherical integer points, few planes, duplicates, equal and hiding weights).
// Every generator is a pure function of its seed, so a failing case is reproduced from the
// seed RapidCheck prints.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <set>
#include <tuple>
#include <vector>

#include "rstruct/geometry/vec3.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"

namespace rstruct::test {

/// splitmix64.
class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  /// Uniform in [0, 1) on the dyadic grid 2^-30 (so power-of-two scalings and integer
  /// translations below 2^22 are exact).
  double uniform() { return static_cast<double>(next() >> 34) * 0x1p-30; }
  int integer(int lo, int hi) {  // inclusive
    return lo + static_cast<int>(next() % static_cast<std::uint64_t>(hi - lo + 1));
  }

 private:
  std::uint64_t state_;
};

inline std::vector<Point3> uniform_points(std::size_t n, std::uint64_t seed) {
  Random r(seed);
  std::vector<Point3> p(n);
  for (Point3& q : p) q = {r.uniform(), r.uniform(), r.uniform()};
  return p;
}

inline std::vector<Point3> grid_points(int nx, int ny, int nz) {
  std::vector<Point3> p;
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) {
      for (int k = 0; k < nz; ++k) p.push_back({double(i), double(j), double(k)});
    }
  }
  return p;
}

/// All integer points with x² + y² + z² = r2 (exactly cospherical).
inline std::vector<Point3> sphere_points(int r2) {
  std::vector<Point3> p;
  const int r = static_cast<int>(std::sqrt(double(r2))) + 1;
  for (int x = -r; x <= r; ++x) {
    for (int y = -r; y <= r; ++y) {
      for (int z = -r; z <= r; ++z) {
        if (x * x + y * y + z * z == r2) p.push_back({double(x), double(y), double(z)});
      }
    }
  }
  return p;
}

/// n points with small integer coordinates on `planes` axis-parallel or diagonal planes.
inline std::vector<Point3> few_plane_points(std::size_t n, int planes, std::uint64_t seed) {
  Random r(seed);
  std::vector<Point3> p(n);
  for (Point3& q : p) {
    const int which = r.integer(0, planes - 1);
    const double a = r.integer(-4, 4);
    const double b = r.integer(-4, 4);
    switch (which % 3) {
      case 0: q = {a, b, double(which)}; break;           // z = which
      case 1: q = {double(which), a, b}; break;           // x = which
      default: q = {a, b, a + b + double(which)}; break;  // z = x + y + which
    }
  }
  return p;
}

/// n points drawn with repetition from a pool of `distinct` small-integer points.
inline std::vector<Point3> duplicate_points(std::size_t n, int distinct, std::uint64_t seed) {
  Random r(seed);
  std::vector<Point3> pool(static_cast<std::size_t>(distinct));
  for (Point3& q : pool) q = {double(r.integer(0, 3)), double(r.integer(0, 3)),
                              double(r.integer(0, 3))};
  std::vector<Point3> p(n);
  for (Point3& q : p) q = pool[static_cast<std::size_t>(r.integer(0, distinct - 1))];
  return p;
}

/// Weights for hidden-heavy inputs: on the dyadic grid, in [0, scale), a quarter of them
/// equal (exact ties), so many points are hidden.
inline std::vector<double> hiding_weights(std::size_t n, double scale, std::uint64_t seed) {
  Random r(seed);
  std::vector<double> w(n);
  for (double& x : w) x = r.integer(0, 3) == 0 ? scale / 4 : r.uniform() * scale;
  return w;
}

/// Points with weights (empty: a Delaunay input).
struct Input {
  std::vector<Point3> points;
  std::vector<double> weights;
};

/// The triangulation of `in`: regular if it has weights, Delaunay otherwise.
inline triangulation::RegularTriangulation3 build(
    const Input& in, const triangulation::TriangulationOptions& options = {}) {
  return in.weights.empty() ? triangulation::RegularTriangulation3(in.points, options)
                            : triangulation::RegularTriangulation3(in.points, in.weights, options);
}

/// n points on the torus of radii 1 and 0.3 around the z axis, uniform in its angles.
inline std::vector<Point3> torus_points(std::size_t n, std::uint64_t seed) {
  Random r(seed);
  std::vector<Point3> p(n);
  for (Point3& q : p) {
    const double u = 2 * std::numbers::pi * r.uniform();
    const double v = 2 * std::numbers::pi * r.uniform();
    q = {(1 + 0.3 * std::cos(v)) * std::cos(u), (1 + 0.3 * std::cos(v)) * std::sin(u),
         0.3 * std::sin(v)};
  }
  return p;
}

/// 20,000 torus points (seed 19) followed by the 8 corners of the cube [-4, 4]^3, which the
/// parallel-insertion tests insert first (TriangulationOptions::insert_first = 8), as the
/// pole analysis does with its box sites.
inline Input torus_with_box_corners() {
  Input in{torus_points(20000, 19), {}};
  for (int k = 0; k < 8; ++k) {
    in.points.push_back({(k & 1) != 0 ? 4.0 : -4.0, (k & 2) != 0 ? 4.0 : -4.0,
                         (k & 4) != 0 ? 4.0 : -4.0});
  }
  return in;
}

/// n uniform points (seed) followed by `copies` exact copies of random ones among them.
inline Input with_duplicates(std::size_t n, std::uint64_t seed, int copies) {
  Input in{uniform_points(n, seed), {}};
  Random r(seed + 1);
  for (int i = 0; i < copies; ++i) {
    const int which = r.integer(0, static_cast<int>(n) - 1);
    in.points.push_back(in.points[static_cast<std::size_t>(which)]);
  }
  return in;
}

using CellKey = std::array<std::uint32_t, 4>;

/// The finite cells as sorted vertex quadruples.
inline std::set<CellKey> cell_set(const triangulation::RegularTriangulation3& t) {
  std::set<CellKey> s;
  t.for_each_finite_cell([&](triangulation::CellId c) {
    CellKey k = t.vertices(c);
    std::sort(k.begin(), k.end());
    s.insert(k);
  });
  return s;
}

}  // namespace rstruct::test
