#pragma once
/// \file
/// The pole distance D̂ (paper Definition 2): D̂(x) = distance from x to the nearest pole of
/// any sample, inner or outer (DESIGN.md §1). Lemma 5.1: lfs(s) ≤ 1.2802·D̂(s) for r ≤ 0.08;
/// Corollary 5.5: 0.817·D̂(s) ≤ l̃fs(s) ≤ D̂(s).
///
/// D̂ is a measurement on constructed points (the poles are rounded circumcentres): it is
/// computed in floating point with a kd-tree over the poles. The nearest pole is the one
/// with the smallest computed squared distance, the smallest index among equal ones: the
/// pole a linear scan in index order finds (pole_distance_brute_force), whatever the tree,
/// the threads or the starting pole; D̂ is the square root of that squared distance's
/// recomputation, so all three functions return the same doubles.

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "rstruct/geometry/vec3.hpp"
#include "rstruct/poles/pole_set.hpp"

namespace rstruct::poles {

struct PoleDistance {
  std::vector<double> distance;          ///< D̂(x_i), one per query point
  std::vector<std::uint32_t> nearest;    ///< index of the nearest pole, one per query point
};

/// D̂ of every point of `points` with respect to `pole_centres`, with a kd-tree.
/// `threads` = 0 picks std::thread::hardware_concurrency().
/// \throws InvalidInput if `pole_centres` is empty while `points` is not, or any input
/// coordinate is not finite.
PoleDistance pole_distance(std::span<const Point3> points, std::span<const Point3> pole_centres,
                           unsigned threads = 0);

/// The same, for the samples of `poles`: each search starts from the nearer of the sample's
/// own poles, which bounds D̂(s) and prunes the kd-tree search early. Same result as
/// pole_distance(samples, poles.centre).
/// \throws InvalidInput as pole_distance, or if samples.size() != poles.sample_count.
PoleDistance pole_distance(std::span<const Point3> samples, const PoleSet& poles,
                           unsigned threads = 0);

/// The same, with `side_task` run on one of the `threads` threads (0: hardware
/// concurrency): that thread joins the queries when the task returns, the others start at
/// once. With one thread (or fewer than 4,096 samples) the task runs after the queries.
/// The task must not write `poles.centre` or `poles.sample_poles` (analyse_poles runs the
/// labeling here, which writes poles.label). An exception from the task stops the queries
/// and is rethrown.
PoleDistance pole_distance_beside(std::span<const Point3> samples, const PoleSet& poles,
                                  unsigned threads, const std::function<void()>& side_task);

/// Reference implementation for tests: a linear scan per point.
PoleDistance pole_distance_brute_force(std::span<const Point3> points,
                                       std::span<const Point3> pole_centres);

}  // namespace rstruct::poles
