#pragma once
// Nearest-neighbour queries over a point set (nanoflann kd-tree), private to sampling.
// The distances are computed in double precision from the stored coordinates: the query
// returns the exact nearest point, and its distance to within a few ulps.

#include <cstddef>
#include <memory>
#include <nanoflann.hpp>
#include <vector>

#include "rstruct/geometry/vec3.hpp"

namespace rstruct::sampling {

class PointIndex {
 public:
  explicit PointIndex(const std::vector<Point3>& points)
      : adaptor_{&points}, tree_(3, adaptor_, nanoflann::KDTreeSingleIndexAdaptorParams(12)) {}

  bool empty() const { return adaptor_.points->empty(); }

  /// Index of a nearest point and the distance to it. \pre !empty().
  std::pair<std::size_t, double> nearest(const Point3& x) const {
    std::size_t index = 0;
    double d2 = 0;
    const double q[3] = {x.x, x.y, x.z};
    tree_.knnSearch(q, 1, &index, &d2);
    return {index, distance(x, (*adaptor_.points)[index])};
  }

 private:
  struct Adaptor {
    const std::vector<Point3>* points;
    std::size_t kdtree_get_point_count() const { return points->size(); }
    double kdtree_get_pt(std::size_t i, std::size_t dim) const { return (*points)[i][dim]; }
    template <class Box>
    bool kdtree_get_bbox(Box&) const {
      return false;
    }
  };
  using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Adaptor>,
                                                   Adaptor, 3, std::size_t>;
  Adaptor adaptor_;
  Tree tree_;
};

}  // namespace rstruct::sampling
