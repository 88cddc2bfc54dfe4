#pragma once
// Exact depth-first branch and bound for small (reduced) set-cover instances: branch on the
// uncovered row with fewest usable columns, one child per column (earlier siblings'
// columns excluded), prune with cost + a packing bound (uncovered rows that share no usable
// column each need a distinct column, at least their cheapest).

#include <cstdint>
#include <vector>

#include "rstruct/core/stopwatch.hpp"
#include "rstruct/setcover/instance.hpp"

namespace rstruct::setcover::detail {

struct BranchAndBoundResult {
  bool finished = false;              ///< search completed: `best` is optimal
  std::vector<std::int32_t> best;     ///< improved cover, empty if none beat the incumbent
  double best_cost = 0.0;
  std::int64_t nodes = 0;
  bool timed_out = false;  ///< unfinished because of the deadline (not the node limit)
};

/// Searches for a cover cheaper than `incumbent_cost`, within `max_nodes` nodes and the
/// deadline. When `finished`, no cover is cheaper than min(best_cost, incumbent_cost).
BranchAndBoundResult branch_and_bound(const Instance& inst, double incumbent_cost,
                                      std::int64_t max_nodes, double deadline,
                                      const Stopwatch& clock);

}  // namespace rstruct::setcover::detail
