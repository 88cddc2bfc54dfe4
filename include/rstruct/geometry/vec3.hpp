#pragma once
/// \file
/// Points and vectors in R³ (doubles). Arithmetic here is plain floating point and is used
/// only for constructions and measurements, never for combinatorial decisions: those go
/// through rstruct/predicates.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace rstruct {

struct Vec3 {
  double x = 0, y = 0, z = 0;

  constexpr double operator[](std::size_t i) const { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr double& operator[](std::size_t i) { return i == 0 ? x : (i == 1 ? y : z); }

  constexpr Vec3& operator+=(const Vec3& o) { x += o.x; y += o.y; z += o.z; return *this; }
  constexpr Vec3& operator-=(const Vec3& o) { x -= o.x; y -= o.y; z -= o.z; return *this; }
  constexpr Vec3& operator*=(double s) { x *= s; y *= s; z *= s; return *this; }
  friend constexpr Vec3 operator+(Vec3 a, const Vec3& b) { return a += b; }
  friend constexpr Vec3 operator-(Vec3 a, const Vec3& b) { return a -= b; }
  friend constexpr Vec3 operator-(const Vec3& a) { return {-a.x, -a.y, -a.z}; }
  friend constexpr Vec3 operator*(Vec3 a, double s) { return a *= s; }
  friend constexpr Vec3 operator*(double s, Vec3 a) { return a *= s; }
  friend constexpr Vec3 operator/(const Vec3& a, double s) { return {a.x / s, a.y / s, a.z / s}; }
  friend constexpr bool operator==(const Vec3& a, const Vec3& b) = default;
};

using Point3 = Vec3;

constexpr double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
constexpr double squared_norm(const Vec3& a) { return dot(a, a); }
inline double norm(const Vec3& a) { return std::sqrt(squared_norm(a)); }
constexpr double squared_distance(const Vec3& a, const Vec3& b) { return squared_norm(a - b); }
inline double distance(const Vec3& a, const Vec3& b) { return std::sqrt(squared_distance(a, b)); }
inline Vec3 normalized(const Vec3& a) { return a / norm(a); }
inline bool is_finite(const Vec3& a) {
  return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}

/// A weighted point (c, w); a ball B(c, r) is the weighted point (c, r²).
/// Power distance of x: |x − c|² − w.
struct WeightedPoint {
  Point3 c;
  double w = 0;
  friend constexpr bool operator==(const WeightedPoint& a, const WeightedPoint& b) = default;
};

/// A ball: centre and radius.
struct Ball {
  Point3 c;
  double r = 0;
  WeightedPoint weighted() const { return {c, r * r}; }
};

/// Floating-point power distance |x − c|² − w (a measurement, not a decision).
constexpr double power_distance(const Point3& x, const WeightedPoint& p) {
  return squared_distance(x, p.c) - p.w;
}

/// Axis-aligned bounding box.
struct Box3 {
  Point3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL};
  Point3 hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  /// A NaN coordinate of p leaves the box as it was (as std::fmin and std::fmax would, but
  /// std::min and std::max with the box's value first compile to plain min/max
  /// instructions: a kd-tree build that bounds every node went 2.5-3x faster).
  void add(const Point3& p) {
    for (std::size_t i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], p[i]);
      hi[i] = std::max(hi[i], p[i]);
    }
  }
  bool empty() const { return lo.x > hi.x; }
  Point3 centre() const { return (lo + hi) * 0.5; }
  Vec3 extent() const { return hi - lo; }
  double diagonal() const { return norm(hi - lo); }
  double max_extent() const {
    const Vec3 e = extent();
    return std::fmax(e.x, std::fmax(e.y, e.z));
  }
};

}  // namespace rstruct
