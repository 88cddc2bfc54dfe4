#pragma once
// Shared helpers of the medial-axis tests: checks of a computed axis against the union.

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include "rstruct/geometry/vec3.hpp"
#include "rstruct/medial/medial_axis.hpp"

namespace rstruct::testing {

/// Signed distance-like depth of x in the union: max over balls of r − |x − c|
/// (positive inside). Double measurement.
inline double union_depth(std::span<const Ball> balls, const Point3& x) {
  double best = -std::numeric_limits<double>::infinity();
  for (const Ball& b : balls) best = std::max(best, b.r - distance(x, b.c));
  return best;
}

/// Extent of the balls' bounding box (the scale of round-off tolerances).
inline double union_extent(std::span<const Ball> balls) {
  Box3 box;
  for (const Ball& b : balls) {
    box.add(b.c - Vec3{b.r, b.r, b.r});
    box.add(b.c + Vec3{b.r, b.r, b.r});
  }
  const Vec3 e = box.hi - box.lo;
  return std::max({e.x, e.y, e.z});
}

/// Fibonacci directions on the unit sphere.
inline std::vector<Vec3> sphere_directions(int count) {
  std::vector<Vec3> out;
  const double golden = std::acos(-1.0) * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / count;
    const double r = std::sqrt(1.0 - z * z);
    out.push_back({r * std::cos(golden * i), r * std::sin(golden * i), z});
  }
  return out;
}

}  // namespace rstruct::testing
