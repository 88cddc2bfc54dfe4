#include "branch_and_bound.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rstruct::setcover::detail {

namespace {

class Search {
 public:
  Search(const Instance& inst, double incumbent, std::int64_t max_nodes, double deadline,
         const Stopwatch& clock)
      : inst_(inst),
        clock_(clock),
        deadline_(deadline),
        max_nodes_(max_nodes),
        cover_count_(static_cast<std::size_t>(inst.num_rows()), 0),
        banned_(static_cast<std::size_t>(inst.num_cols()), 0),
        mark_(static_cast<std::size_t>(inst.num_cols()), 0) {
    result.best_cost = incumbent;
    slack_ = inst.has_integer_costs() ? 0.5 : 1e-9 * std::max(1.0, std::abs(incumbent));
  }

  void run() {
    aborted_ = false;
    dfs(0.0);
    result.finished = !aborted_;
  }

  BranchAndBoundResult result;

 private:
  /// Lower bound on the cost still needed: a greedy packing of uncovered rows with pairwise
  /// disjoint usable columns, each contributing its cheapest usable column.
  double packing_bound(std::int32_t& branch_row) {
    double bound = 0.0;
    ++epoch_;
    branch_row = -1;
    std::size_t fewest = std::numeric_limits<std::size_t>::max();
    for (std::int32_t i = 0; i < inst_.num_rows(); ++i) {
      if (cover_count_[i] > 0) continue;
      double cheapest = std::numeric_limits<double>::infinity();
      bool disjoint = true;
      std::size_t usable = 0;
      for (std::int32_t j : inst_.row(i)) {
        if (banned_[j]) continue;
        ++usable;
        cheapest = std::min(cheapest, inst_.cost(j));
        if (mark_[j] == epoch_) disjoint = false;
      }
      if (usable == 0) return std::numeric_limits<double>::infinity();
      if (usable < fewest) {
        fewest = usable;
        branch_row = i;
      }
      if (disjoint) {
        bound += cheapest;
        for (std::int32_t j : inst_.row(i)) mark_[j] = epoch_;
      }
    }
    return bound;
  }

  void take(std::int32_t j, int delta) {
    for (std::int32_t i : inst_.column(j)) cover_count_[i] += delta;
  }

  void dfs(double cost) {
    if (aborted_) return;
    if (++result.nodes > max_nodes_) {
      aborted_ = true;
      return;
    }
    if ((result.nodes & 1023) == 0 && clock_.seconds() > deadline_) {
      aborted_ = true;
      result.timed_out = true;
      return;
    }
    std::int32_t row = -1;
    const double bound = packing_bound(row);
    if (cost + bound >= result.best_cost - slack_) return;
    if (row < 0) {  // everything covered and cheaper than the incumbent
      result.best = chosen_;
      result.best_cost = cost;
      return;
    }
    std::vector<std::int32_t> options;
    for (std::int32_t j : inst_.row(row)) {
      if (!banned_[j]) options.push_back(j);
    }
    std::sort(options.begin(), options.end(), [&](std::int32_t a, std::int32_t b) {
      return inst_.cost(a) < inst_.cost(b) || (inst_.cost(a) == inst_.cost(b) && a < b);
    });
    std::vector<std::int32_t> banned_here;
    for (std::int32_t j : options) {
      chosen_.push_back(j);
      take(j, +1);
      banned_[j] = 1;  // a chosen column is never chosen twice below
      dfs(cost + inst_.cost(j));
      take(j, -1);
      chosen_.pop_back();
      banned_here.push_back(j);  // later siblings exclude it: no duplicate subtrees
      if (aborted_) break;
    }
    for (std::int32_t j : banned_here) banned_[j] = 0;
  }

  const Instance& inst_;
  const Stopwatch& clock_;
  double deadline_;
  std::int64_t max_nodes_;
  double slack_ = 0.0;
  bool aborted_ = false;
  std::vector<std::int32_t> cover_count_;
  std::vector<char> banned_;
  std::vector<std::int64_t> mark_;
  std::int64_t epoch_ = 0;
  std::vector<std::int32_t> chosen_;
};

}  // namespace

BranchAndBoundResult branch_and_bound(const Instance& inst, double incumbent_cost,
                                      std::int64_t max_nodes, double deadline,
                                      const Stopwatch& clock) {
  Search search(inst, incumbent_cost, max_nodes, deadline, clock);
  search.run();
  return std::move(search.result);
}

}  // namespace rstruct::setcover::detail
