#include "rstruct/pipeline/prune_balls.hpp"

#include <cstdint>
#include <span>
#include <string>

#include "rstruct/core/error.hpp"
#include "rstruct/core/report.hpp"
#include "rstruct/poles/covering_sets.hpp"
#include "rstruct/setcover/instance.hpp"
#include "rstruct/setcover/solver.hpp"

namespace rstruct::pipeline {

PruneResult prune_balls(std::span<const Ball> shrunk, std::span<const Point3> points,
                        const PruneOptions& options, Report* report) {
  Stopwatch total;
  PruneResult result;
  Report scratch;
  Report& rep = report ? *report : scratch;

  Report::Stage sets_stage(rep, "covering sets");
  // The sets and their conversion are gone before the solver starts: with 10^6 samples
  // the matrix has ~10^8 entries, and every copy of it costs 4 bytes per entry.
  const setcover::Instance instance = [&] {
    const poles::CoveringSets sets = poles::covering_sets(shrunk, points, options.threads);
    result.entries = sets.entry_count();
    // The set-cover module works on signed 32-bit rows and 64-bit offsets. The rows are
    // read in place (int32 may alias uint32; every row id is below row_count <= 2^31 - 1)
    // and copied once, into the arrays the instance takes over.
    if (sets.row_count > static_cast<std::uint32_t>(INT32_MAX)) {
      throw InvalidInput("pruning: more than 2^31 - 1 points");
    }
    const auto* rows = reinterpret_cast<const std::int32_t*>(sets.rows.data());
    return setcover::Instance::from_csr(
        static_cast<std::int32_t>(sets.row_count),
        std::vector<std::int64_t>(sets.column_offsets.begin(), sets.column_offsets.end()),
        std::vector<std::int32_t>(rows, rows + sets.rows.size()), {}, options.threads);
  }();
  sets_stage.finish();

  if (const std::int32_t row = instance.first_uncoverable_row(); row >= 0) {
    throw ComputationFailed("pruning: point " + std::to_string(row) +
                            " is covered by no shrunk ball");
  }
  Report::Stage cover_stage(rep, "set cover");
  setcover::SolverOptions solver_options;
  solver_options.time_limit = options.time_limit;
  if (options.iterations > 0) {
    solver_options.max_local_search_iterations = options.iterations;
    solver_options.max_subgradient_iterations = options.subgradient_iterations;
  }
  solver_options.seed = options.seed;
  solver_options.threads = options.threads;
  const setcover::Solution solution = setcover::solve(instance, solver_options);
  cover_stage.finish();

  result.kept.assign(solution.columns.begin(), solution.columns.end());
  result.cost = solution.cost;
  result.lower_bound = solution.lower_bound;
  result.gap = solution.gap;
  result.optimal = solution.optimal;
  result.solver_options = solver_options;
  result.solver = solution.stats;
  result.seconds = total.seconds();
  return result;
}

}  // namespace rstruct::pipeline
