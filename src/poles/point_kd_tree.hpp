#pragma once
// A kd-tree over a span of points (nanoflann), used for the pole distance D̂ and for the
// covering sets. Searches here only *propose* candidates: nanoflann's distances are plain
// floating point, so every radius query is run with a slightly inflated radius and the
// caller decides membership with an exact predicate (predicates::side_of_ball).

#include <cstdint>
#include <span>
#include <vector>

#include <nanoflann.hpp>

#include "rstruct/geometry/vec3.hpp"

namespace rstruct::poles::detail {

class PointKdTree {
 public:
  /// Builds the tree over `points` (kept by reference: the span must outlive the tree).
  explicit PointKdTree(std::span<const Point3> points)
      : adaptor_{points}, tree_(3, adaptor_, nanoflann::KDTreeSingleIndexAdaptorParams(12)) {}
  PointKdTree(const PointKdTree&) = delete;  // the tree refers to adaptor_
  PointKdTree& operator=(const PointKdTree&) = delete;

  std::size_t size() const { return adaptor_.points.size(); }

  /// Index of a point nearest to q in floating-point distance (ties: any). \pre size() > 0.
  std::uint32_t nearest(const Point3& q, double* squared_distance_out = nullptr) const {
    std::uint32_t index = 0;
    double d2 = 0;
    const double query[3] = {q.x, q.y, q.z};
    tree_.knnSearch(query, 1, &index, &d2);
    if (squared_distance_out != nullptr) *squared_distance_out = d2;
    return index;
  }

  /// Like nearest(), but starts from a known candidate: the point `index` at computed
  /// squared distance `squared_distance` (as computed by rstruct::squared_distance, whose
  /// summation order nanoflann shares). The search then prunes every subtree farther than
  /// that, which makes it much faster when the candidate is close. Returns a point whose
  /// squared distance is the minimum (ties: the candidate is kept).
  std::uint32_t nearest_from(const Point3& q, std::uint32_t index, double squared_distance) const {
    Nearest result{squared_distance, index};
    const double query[3] = {q.x, q.y, q.z};
    tree_.findNeighbors(result, query, nanoflann::SearchParams());
    return result.index;
  }

  /// Appends to `out` the indices of every point p with |p − q| ≤ r, and possibly a few
  /// more within a relative margin (the search radius is inflated so that floating-point
  /// rounding inside the tree can never lose a point at distance ≤ r).
  void candidates_within(const Point3& q, double r, std::vector<std::uint32_t>& out) const {
    Collector collector{inflated_squared_radius(r), out};
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
    bool full() const { return true; }
    double worstDist() const { return radius_squared; }
    bool addPoint(double d2, std::uint32_t index) {
      if (d2 <= radius_squared) out.push_back(index);
      return true;
    }
  };
  struct Nearest {
    double d2;
    std::uint32_t index;
    bool full() const { return true; }
    double worstDist() const { return d2; }
    bool addPoint(double d, std::uint32_t i) {
      if (d < d2) {
        d2 = d;
        index = i;
      }
      return true;
    }
  };
  using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Adaptor>,
                                                   Adaptor, 3, std::uint32_t>;
  Adaptor adaptor_;
  Tree tree_;
};

}  // namespace rstruct::poles::detail
