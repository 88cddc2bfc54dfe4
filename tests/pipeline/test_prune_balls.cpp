// Pruning by set cover (prune_balls.hpp) under its default work budget: the kept set is a
// function of the balls, the points, the seed and the budget only, so it repeats from run to
// run and across thread counts (the former wall-clock budget made it depend on the
// machine's speed and load, and on whether the local-search streams ran side by side or one
// after another), and the solver's reported iteration counts stay within the budget.

#include "rstruct/pipeline/prune_balls.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "rstruct/sampling/sample_request.hpp"

using rstruct::Ball;
using rstruct::Point3;
using rstruct::pipeline::PruneOptions;
using rstruct::pipeline::PruneResult;
using rstruct::setcover::SearchLimit;

namespace {

/// Uniform samples of the double torus, and a ball of one radius (2 % of the bounding-box
/// diagonal) around each: a unicost instance with tens of rows per column, large enough
/// that neither the bound nor the exact search settles it and the local search decides.
struct BallInstance {
  std::vector<Point3> points;
  std::vector<Ball> balls;
};

BallInstance double_torus_instance(std::size_t n) {
  rstruct::sampling::SampleRequest request;
  request.shape = "double-torus";
  request.n = n;
  request.seed = 3;
  BallInstance out;
  out.points = rstruct::sampling::generate_sample(request).points;
  Point3 lo = out.points.front();
  Point3 hi = lo;
  for (const Point3& p : out.points) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  const double diagonal = std::sqrt((hi.x - lo.x) * (hi.x - lo.x) + (hi.y - lo.y) * (hi.y - lo.y) +
                                    (hi.z - lo.z) * (hi.z - lo.z));
  for (const Point3& p : out.points) out.balls.push_back(Ball{p, 0.02 * diagonal});
  return out;
}

}  // namespace

TEST_CASE("prune_balls: the default work budget gives the same kept set on every run and "
          "thread count") {
  const BallInstance inst = double_torus_instance(6000);
  PruneOptions options;  // the defaults: a work budget, time only as a safety cap
  REQUIRE(options.iterations > 0);
  options.threads = 1;
  const PruneResult first = rstruct::pipeline::prune_balls(inst.balls, inst.points, options);
  const PruneResult second = rstruct::pipeline::prune_balls(inst.balls, inst.points, options);
  options.threads = 2;
  const PruneResult parallel = rstruct::pipeline::prune_balls(inst.balls, inst.points, options);
  INFO("cover " << first.cost << ", bound " << first.lower_bound << ", "
                << first.solver.local_search_iterations << " local-search iterations");
  // Not settled before the local search, which ran its whole budget in every stream.
  REQUIRE_FALSE(first.optimal);
  REQUIRE(first.solver.local_search_iterations > 0);
  REQUIRE(first.solver.stopped_by == SearchLimit::kIterations);
  CHECK(second.solver.stopped_by == SearchLimit::kIterations);
  CHECK(parallel.solver.stopped_by == SearchLimit::kIterations);
  CHECK(first.kept == second.kept);
  CHECK(first.kept == parallel.kept);
  CHECK(first.lower_bound == parallel.lower_bound);
  CHECK(first.solver.local_search_iterations == parallel.solver.local_search_iterations);
  CHECK(first.solver.subgradient_iterations == parallel.solver.subgradient_iterations);
}

TEST_CASE("prune_balls: reported iteration counts stay within the work budget") {
  const BallInstance inst = double_torus_instance(3000);
  for (const std::int64_t budget : {std::int64_t{1}, std::int64_t{777}, std::int64_t{5000}}) {
    PruneOptions options;
    options.iterations = budget;
    options.subgradient_iterations = 7;
    const PruneResult r = rstruct::pipeline::prune_balls(inst.balls, inst.points, options);
    INFO("budget " << budget << ": " << r.solver.local_search_iterations
                   << " local-search, " << r.solver.subgradient_iterations
                   << " subgradient iterations over " << r.solver.components << " components");
    CHECK(r.solver_options.max_local_search_iterations == budget);
    CHECK(r.solver_options.max_subgradient_iterations == 7);
    CHECK(r.solver_options.time_limit == options.time_limit);
    CHECK(r.solver.stopped_by != SearchLimit::kTime);
    CHECK(r.solver.local_search_iterations <=
          budget * r.solver_options.local_search_streams);
    CHECK(r.solver.subgradient_iterations <= 7 * r.solver.components);
    // A budget of 1 is shared out as none to most components (the shares add up to it).
    if (budget > 100) CHECK(r.solver.local_search_iterations > 0);
  }
  // Time only (iterations 0): the solver's own subgradient limit and no local-search limit.
  PruneOptions time_only;
  time_only.iterations = 0;
  time_only.time_limit = 0.2;
  const PruneResult r = rstruct::pipeline::prune_balls(inst.balls, inst.points, time_only);
  CHECK(r.solver_options.max_local_search_iterations == 0);
  CHECK(r.solver_options.max_subgradient_iterations ==
        rstruct::setcover::SolverOptions{}.max_subgradient_iterations);
  CHECK(r.kept.size() == static_cast<std::size_t>(r.cost));
}
