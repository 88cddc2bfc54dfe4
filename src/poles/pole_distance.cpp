#include "rstruct/poles/pole_distance.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

#include "parallel_blocks.hpp"
#include "point_kd_tree.hpp"
#include "spatial_order.hpp"
#include "rstruct/core/error.hpp"

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

/// Runs nearest(i) → pole index for every point in blocks over threads, and fills D̂.
template <class Nearest>
PoleDistance run_queries(std::span<const Point3> points, std::span<const Point3> poles,
                         unsigned threads, Nearest&& nearest) {
  PoleDistance result;
  result.distance.resize(points.size());
  result.nearest.resize(points.size());
  if (points.empty()) return result;
  const unsigned hardware = std::max(1U, std::thread::hardware_concurrency());
  const std::size_t useful = std::max<std::size_t>(1, points.size() / 8192);
  const auto t = static_cast<unsigned>(
      std::min<std::size_t>(threads != 0 ? threads : hardware, useful));
  // Queries in Morton order: consecutive searches walk the same part of the tree.
  const std::vector<std::uint32_t> order = detail::morton_order(points);
  const std::size_t chunk = (points.size() + t - 1) / t;
  detail::run_blocks(t, [&](unsigned k) {
    const std::size_t begin = std::min(points.size(), k * chunk);
    const std::size_t end = std::min(points.size(), begin + chunk);
    for (std::size_t position = begin; position < end; ++position) {
      const std::uint32_t i = order[position];
      result.nearest[i] = nearest(i);
      result.distance[i] = distance(points[i], poles[result.nearest[i]]);
    }
  });
  return result;
}

}  // namespace

PoleDistance pole_distance(std::span<const Point3> points, std::span<const Point3> pole_centres,
                           unsigned threads) {
  check_inputs(points, pole_centres);
  if (points.empty()) return {};
  const detail::PointKdTree tree(pole_centres);
  return run_queries(points, pole_centres, threads,
                     [&](std::size_t i) { return tree.nearest(points[i]); });
}

PoleDistance pole_distance(std::span<const Point3> samples, const PoleSet& poles,
                           unsigned threads) {
  if (samples.size() != poles.sample_count) {
    throw InvalidInput("pole distance: " + std::to_string(samples.size()) +
                       " samples given for a pole set of " + std::to_string(poles.sample_count));
  }
  check_inputs(samples, poles.centre);
  if (samples.empty()) return {};
  const detail::PointKdTree tree(poles.centre);
  return run_queries(samples, poles.centre, threads, [&](std::size_t i) {
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
  });
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
