#include "rstruct/poles/pole_distance.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <mutex>

#include "point_tree.hpp"
#include "spatial_order.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/core/parallel.hpp"

namespace rstruct::poles {
namespace {

void check_inputs(std::span<const Point3> points, std::span<const Point3> poles) {
  if (poles.empty() && !points.empty()) {
    throw InvalidInput("pole distance: there are no poles");
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!is_finite(points[i])) {
      throw InvalidInput("pole distance: point " + std::to_string(i) + " is not finite");
    }
  }
  for (std::size_t i = 0; i < poles.size(); ++i) {
    if (!is_finite(poles[i])) {
      throw InvalidInput("pole distance: pole " + std::to_string(i) + " is not finite");
    }
  }
}

/// Runs nearest(i) → pole index for every point (at least one) and fills D̂. The queries
/// go in Morton order (consecutive searches walk the same part of the tree), in blocks
/// that the workers take in turn, so the worker that runs `side` first still gets its
/// share after.
template <class Nearest>
PoleDistance run_queries(std::span<const Point3> points, std::span<const Point3> poles,
                         unsigned threads, Nearest&& nearest,
                         const std::function<void()>* side = nullptr) {
  PoleDistance result;
  result.distance.resize(points.size());
  result.nearest.resize(points.size());
  std::once_flag side_once;
  const auto run_side = [&] {
    if (side != nullptr) std::call_once(side_once, *side);
  };
  const std::vector<std::uint32_t> order = detail::morton_order(points);
  constexpr std::size_t kBlock = 2048;
  const unsigned t = thread_count(threads, points.size(), side != nullptr ? kBlock : 4 * kBlock);
  parallel_chunks(points.size(), t, kBlock, [&](std::size_t begin, std::size_t end, unsigned w) {
    if (w + 1 == t && t > 1) run_side();  // the last worker, before its first block
    for (std::size_t position = begin; position < end; ++position) {
      const std::uint32_t i = order[position];
      result.nearest[i] = nearest(i);
      result.distance[i] = distance(points[i], poles[result.nearest[i]]);
    }
  });
  run_side();  // one thread, or the last worker got no block
  return result;
}

/// D̂ of the samples of `poles`, each search starting from the nearer of the sample's own
/// poles; `side` (if any) as pole_distance_beside runs it.
PoleDistance sample_pole_distance(std::span<const Point3> samples, const PoleSet& poles,
                                  unsigned threads, const std::function<void()>* side) {
  if (samples.size() != poles.sample_count) {
    throw InvalidInput("pole distance: " + std::to_string(samples.size()) +
                       " samples given for a pole set of " + std::to_string(poles.sample_count));
  }
  check_inputs(samples, poles.centre);
  if (samples.empty()) {
    if (side != nullptr) (*side)();
    return {};
  }
  // The nearest pole lies on the far side of a large empty ball, whose boundary crosses
  // many leaves: see point_tree.hpp for the tree, its .cpp for the figures.
  const detail::PointTree tree(poles.centre, detail::PointTree::kDefaultLeafSize,
                               detail::PointTree::Scan::best, threads);
  const auto from_own_poles = [&](std::size_t i) {
    std::uint32_t best = kNoPole;
    double best_d2 = HUGE_VAL;
    for (const std::uint32_t p : poles.sample_poles[i]) {
      if (p == kNoPole) continue;
      const double d2 = squared_distance(samples[i], poles.centre[p]);
      if (d2 < best_d2) {
        best_d2 = d2;
        best = p;
      }
    }
    return best == kNoPole ? tree.nearest(samples[i]) : tree.nearest_from(samples[i], best, best_d2);
  };
  return run_queries(samples, poles.centre, threads, from_own_poles, side);
}

}  // namespace

PoleDistance pole_distance(std::span<const Point3> points, std::span<const Point3> pole_centres,
                           unsigned threads) {
  check_inputs(points, pole_centres);
  if (points.empty()) return {};
  const detail::PointTree tree(pole_centres, detail::PointTree::kDefaultLeafSize,
                               detail::PointTree::Scan::best, threads);
  return run_queries(points, pole_centres, threads,
                     [&](std::size_t i) { return tree.nearest(points[i]); });
}

PoleDistance pole_distance(std::span<const Point3> samples, const PoleSet& poles,
                           unsigned threads) {
  return sample_pole_distance(samples, poles, threads, nullptr);
}

PoleDistance pole_distance_beside(std::span<const Point3> samples, const PoleSet& poles,
                                  unsigned threads, const std::function<void()>& side_task) {
  return sample_pole_distance(samples, poles, threads, &side_task);
}

PoleDistance pole_distance_brute_force(std::span<const Point3> points,
                                       std::span<const Point3> pole_centres) {
  check_inputs(points, pole_centres);
  PoleDistance result;
  for (const Point3& x : points) {
    std::uint32_t best = 0;
    double best_d2 = HUGE_VAL;
    for (std::size_t j = 0; j < pole_centres.size(); ++j) {
      const double d2 = squared_distance(x, pole_centres[j]);
      if (d2 < best_d2) {
        best_d2 = d2;
        best = static_cast<std::uint32_t>(j);
      }
    }
    result.nearest.push_back(best);
    result.distance.push_back(distance(x, pole_centres[best]));
  }
  return result;
}

}  // namespace rstruct::poles
