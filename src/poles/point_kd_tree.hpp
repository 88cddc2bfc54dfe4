#pragma once
// A kd-tree over a span of points (nanoflann), used for the covering sets (the pole
// distance D̂ has its own, nearest_point_tree.hpp). Searches here only *propose*
// candidates: nanoflann's distances are plain floating point, so every radius query is run
// with a slightly inflated radius and the caller decides membership with an exact
// predicate (predicates::side_of_ball).
// The tree keeps its own copy of the points in Morton order, so that a leaf's points are
// contiguous in memory; every index it returns is an index into the caller's span.

#include <cstdint>
#include <span>
#include <vector>

#include <nanoflann.hpp>

#include "rstruct/geometry/vec3.hpp"
#include "spatial_order.hpp"

namespace rstruct::poles::detail {

class PointKdTree {
 public:
  /// Builds the tree over a copy of `points`, with up to 12 points per leaf (leaves of 24
  /// made the covering sets' queries only 5 % faster: 300,000 balls of the 10^6 torus,
  /// 0.355 -> 0.338 s).
  explicit PointKdTree(std::span<const Point3> points)
      : order_(morton_order(points)),
        sorted_(reordered(points, order_)),
        adaptor_{sorted_},
        tree_(3, adaptor_, nanoflann::KDTreeSingleIndexAdaptorParams(12)) {}
  PointKdTree(const PointKdTree&) = delete;  // the tree refers to adaptor_
  PointKdTree& operator=(const PointKdTree&) = delete;

  std::size_t size() const { return sorted_.size(); }

  /// Appends to `out` the indices of every point p with |p − q| ≤ r, and possibly a few
  /// more within a relative margin (the search radius is inflated so that floating-point
  /// rounding inside the tree can never lose a point at distance ≤ r).
  void candidates_within(const Point3& q, double r, std::vector<std::uint32_t>& out) const {
    Collector collector{inflated_squared_radius(r), out, order_};
    const double query[3] = {q.x, q.y, q.z};
    tree_.findNeighbors(collector, query, nanoflann::SearchParams(32, 0.0F, false));
  }

  /// r² enlarged by a relative 2⁻²⁰ plus the smallest normal double: far above the
  /// few-ulp rounding of nanoflann's distance sums, far below any geometric scale.
  static double inflated_squared_radius(double r) {
    return r * r * (1.0 + 0x1p-20) + 0x1p-1022;
  }

 private:
  struct Adaptor {
    std::span<const Point3> points;
    std::size_t kdtree_get_point_count() const { return points.size(); }
    double kdtree_get_pt(std::size_t index, std::size_t dim) const { return points[index][dim]; }
    template <class Box>
    bool kdtree_get_bbox(Box& /*unused*/) const {
      return false;
    }
  };
  struct Collector {
    double radius_squared;
    std::vector<std::uint32_t>& out;
    const std::vector<std::uint32_t>& order;
    bool full() const { return true; }
    double worstDist() const { return radius_squared; }
    bool addPoint(double d2, std::uint32_t index) {
      if (d2 <= radius_squared) out.push_back(order[index]);
      return true;
    }
  };
  static std::vector<Point3> reordered(std::span<const Point3> points,
                                       const std::vector<std::uint32_t>& order) {
    std::vector<Point3> sorted(points.size());
    for (std::size_t k = 0; k < order.size(); ++k) sorted[k] = points[order[k]];
    return sorted;
  }
  using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Adaptor>,
                                                   Adaptor, 3, std::uint32_t>;
  std::vector<std::uint32_t> order_;  // tree position → caller's index
  std::vector<Point3> sorted_;
  Adaptor adaptor_;
  Tree tree_;
};

}  // namespace rstruct::poles::detail
