#pragma once
// Measurement geometry of the lemma property tests (tests/lemmas/): distances from a point
// to segments and triangles, the parameter interval of a segment inside a ball, angles,
// and a spatial index answering "which simplices of a complex come within distance D of
// q". Everything here is plain double arithmetic: these are measurements of constructed
// points (poles, circumcentres), compared against the paper's bounds with the margins
// reported, never combinatorial decisions of the pipeline.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "poles/point_tree.hpp"
#include "rstruct/geometry/vec3.hpp"

namespace rstruct::lemmas {

inline constexpr double kPi = 3.14159265358979323846;

inline double degrees(double radians) { return radians * 180.0 / kPi; }

/// Angle between two non-zero vectors in degrees (atan2 form: accurate near 0 and 180°).
inline double angle_deg(const Vec3& a, const Vec3& b) {
  return degrees(std::atan2(norm(cross(a, b)), dot(a, b)));
}

/// Exterior angle of intersection of two spheres (radii r1, r2, centres d apart): the
/// angle between the two radii at a common point subtracted from 180°. Concentric-like
/// (deeply overlapping) spheres give 180°, tangent ones 0°. NaN when they do not meet.
inline double exterior_intersection_angle_deg(double r1, double r2, double d) {
  const double c = (d * d - r1 * r1 - r2 * r2) / (2.0 * r1 * r2);
  if (c < -1.0 - 1e-12 || c > 1.0 + 1e-12) return std::nan("");
  return degrees(std::acos(std::clamp(c, -1.0, 1.0)));
}

/// Squared distance from q to the segment ab.
inline double squared_distance_to_segment(const Point3& q, const Point3& a, const Point3& b) {
  const Vec3 ab = b - a;
  const double len2 = squared_norm(ab);
  double t = len2 > 0 ? dot(q - a, ab) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return squared_distance(q, a + ab * t);
}

/// Squared distance from q to the triangle abc (closest-point regions of the triangle,
/// Ericson, Real-Time Collision Detection §5.1.5).
inline double squared_distance_to_triangle(const Point3& q, const Point3& a, const Point3& b,
                                           const Point3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = q - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return squared_distance(q, a);
  const Vec3 bp = q - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return squared_distance(q, b);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return squared_distance(q, a + ab * (d1 / (d1 - d3)));
  const Vec3 cp = q - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return squared_distance(q, c);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return squared_distance(q, a + ac * (d2 / (d2 - d6)));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    return squared_distance(q, b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))));
  }
  const double denom = 1.0 / (va + vb + vc);
  return squared_distance(q, a + ab * (vb * denom) + ac * (vc * denom));
}

/// The parameters t ∈ [0, 1] with a + t(b − a) in the closed ball B(c, radius), as an
/// interval, or nullopt if the segment misses the ball.
inline std::optional<std::pair<double, double>> segment_ball_interval(const Point3& a,
                                                                      const Point3& b,
                                                                      const Point3& c,
                                                                      double radius) {
  const Vec3 d = b - a, f = a - c;
  const double qa = squared_norm(d), qb = 2.0 * dot(f, d), qc = squared_norm(f) - radius * radius;
  if (qa == 0) {
    if (qc <= 0) return std::pair{0.0, 1.0};
    return std::nullopt;
  }
  const double disc = qb * qb - 4.0 * qa * qc;
  if (disc < 0) return std::nullopt;
  const double root = std::sqrt(disc);
  // Numerically stable roots of qa t² + qb t + qc.
  const double q = -0.5 * (qb + std::copysign(root, qb));
  double t0 = q / qa, t1 = q != 0 ? qc / q : -qb / (2 * qa);
  if (t0 > t1) std::swap(t0, t1);
  t0 = std::max(t0, 0.0);
  t1 = std::min(t1, 1.0);
  if (t0 > t1) return std::nullopt;
  return std::pair{t0, t1};
}

/// A simplex (vertex, edge or triangle) of a complex embedded by its vertex positions.
struct EmbeddedSimplex {
  std::array<std::uint32_t, 3> v{};  ///< vertex ids (only the first `size` are used)
  int size = 1;
};

/// Squared distance from q to an embedded simplex.
inline double squared_distance_to(const Point3& q, const EmbeddedSimplex& s,
                                  std::span<const Point3> position) {
  if (s.size == 1) return squared_distance(q, position[s.v[0]]);
  if (s.size == 2) return squared_distance_to_segment(q, position[s.v[0]], position[s.v[1]]);
  return squared_distance_to_triangle(q, position[s.v[0]], position[s.v[1]], position[s.v[2]]);
}

/// Finds the simplices within distance D of a query point. Each simplex is represented by
/// the centre and radius of a ball containing it (vertex centroid, farthest vertex); the
/// balls are grouped by radius into classes [2^k, 2^(k+1)), each with its own kd-tree over
/// the centres, queried with radius D + the class's largest radius. So a few huge simplices
/// (long edges between far poles) do not slow down every query.
class SimplexIndex {
 public:
  SimplexIndex(std::vector<EmbeddedSimplex> simplices, std::span<const Point3> position)
      : simplices_(std::move(simplices)), position_(position.begin(), position.end()) {
    std::vector<std::vector<std::uint32_t>> members;
    std::vector<int> exponents;
    std::vector<Point3> centre(simplices_.size());
    std::vector<double> radius(simplices_.size());
    for (std::uint32_t i = 0; i < simplices_.size(); ++i) {
      const EmbeddedSimplex& s = simplices_[i];
      Vec3 sum{};
      for (int k = 0; k < s.size; ++k) sum = sum + position_[s.v[static_cast<std::size_t>(k)]];
      centre[i] = sum / static_cast<double>(s.size);
      double r = 0;
      for (int k = 0; k < s.size; ++k) {
        r = std::max(r, distance(centre[i], position_[s.v[static_cast<std::size_t>(k)]]));
      }
      radius[i] = r;
      const int e = r > 0 ? std::ilogb(r) : -1074;
      auto it = std::find(exponents.begin(), exponents.end(), e);
      if (it == exponents.end()) {
        exponents.push_back(e);
        members.emplace_back();
        it = exponents.end() - 1;
      }
      members[static_cast<std::size_t>(it - exponents.begin())].push_back(i);
    }
    for (std::size_t k = 0; k < members.size(); ++k) {
      std::vector<Point3> centres;
      double max_radius = 0;
      for (const std::uint32_t i : members[k]) {
        centres.push_back(centre[i]);
        max_radius = std::max(max_radius, radius[i]);
      }
      groups_.push_back(Group{members[k], max_radius, poles::detail::PointTree(centres)});
    }
  }

  std::size_t size() const { return simplices_.size(); }
  const EmbeddedSimplex& simplex(std::uint32_t i) const { return simplices_[i]; }

  /// Appends to `out` (cleared first) every simplex id within distance D of q (and
  /// possibly some a little farther; callers measure the exact distance themselves).
  void within(const Point3& q, double d, std::vector<std::uint32_t>& out) const {
    out.clear();
    std::vector<std::uint32_t> found;
    for (const Group& group : groups_) {
      found.clear();
      group.tree.candidates_within(q, d + group.max_radius, found);
      for (const std::uint32_t k : found) out.push_back(group.ids[k]);
    }
  }

  /// Distance from q to the nearest simplex within `cap` of q, or +∞ if none.
  double distance_within(const Point3& q, double cap, std::vector<std::uint32_t>& scratch) const {
    within(q, cap, scratch);
    double best = HUGE_VAL;
    for (const std::uint32_t i : scratch) {
      best = std::min(best, squared_distance_to(q, simplices_[i], position_));
    }
    const double d = std::sqrt(best);
    return d <= cap ? d : HUGE_VAL;
  }

  double squared_distance_to_simplex(const Point3& q, std::uint32_t i) const {
    return squared_distance_to(q, simplices_[i], position_);
  }
  const Point3& position(std::uint32_t v) const { return position_[v]; }

 private:
  struct Group {
    std::vector<std::uint32_t> ids;
    double max_radius = 0;
    poles::detail::PointTree tree;  // over the balls' centres, indices into ids
  };
  std::vector<EmbeddedSimplex> simplices_;
  std::vector<Point3> position_;
  std::vector<Group> groups_;
};

}  // namespace rstruct::lemmas
