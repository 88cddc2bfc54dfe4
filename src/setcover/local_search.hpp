#pragma once
// Row-weighting local search for set cover, after RWLS (Gao, Weise, Li 2015: "An efficient
// local search heuristic with row weighting for the unicost set covering problem"), extended
// to weighted costs by comparing score / cost. The search keeps the current cost below the
// best found, removing columns with the smallest weighted loss and adding, for a random
// uncovered row, its column with the largest weighted gain; rows that stay uncovered gain
// weight. Time stamps and configuration checking break cycles (RWLS's rule: a removed
// column may be re-added once a column sharing one of its rows changed state); after
// 50,000 iterations without improvement the search restarts from the best cover with unit
// weights and a new random stream. Unicost instances use RWLS's order (drop, then repair);
// weighted ones add first and then drop.

#include <atomic>
#include <cstdint>
#include <vector>

#include "rstruct/core/stopwatch.hpp"
#include "rstruct/setcover/instance.hpp"

namespace rstruct::setcover::detail {

struct LocalSearchOptions {
  std::int64_t max_iterations = 1'000'000;
  double deadline = 1.0;  ///< seconds on the clock
  std::uint64_t seed = 1;
  /// Stop as soon as a cover of cost <= target is found (a proven lower bound).
  double target = 0.0;
  /// Shared by concurrent searches (may be null): checked with the deadline, and set when
  /// this search reaches the target, so that the others stop too.
  std::atomic<bool>* stop = nullptr;
};

struct LocalSearchResult {
  std::vector<std::int32_t> best;  ///< best cover found (may be `start` itself)
  double best_cost = 0.0;
  std::int64_t iterations = 0;    ///< at most LocalSearchOptions::max_iterations
  double seconds_to_best = 0.0;  ///< clock reading when the best was found
  bool timed_out = false;        ///< the deadline ended the search
  bool hit_iteration_limit = false;
};

/// Improves the cover `start` (cost `start_cost`) of `inst`. Columns in `start` need not
/// form a cover if `start_cost` is the cost of some known cover elsewhere; the result then
/// holds the first cover found cheaper than it, or is empty.
LocalSearchResult row_weighting_search(const Instance& inst, const std::vector<std::int32_t>& start,
                                       double start_cost, const LocalSearchOptions& options,
                                       const Stopwatch& clock);

}  // namespace rstruct::setcover::detail
