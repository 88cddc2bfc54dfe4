#include "local_search.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>

#include "rstruct/core/assert.hpp"

namespace rstruct::setcover::detail {

namespace {

/// Configuration checking: false = RWLS's rule (a column becomes addable again when any
/// column sharing a row changes state; a sweep over the neighbours per move), true = a
/// cheaper row rule (when one of its rows changes between covered and uncovered). With
/// restarts, RWLS's rule reached 29/30 unicost best-known values against 26/30.
constexpr bool kRowConfiguration = false;
/// Iterations without a better cover after which the search restarts from the best cover
/// with unit weights and a new random stream (diversification). Measured on OR-Library's
/// unicost A family (10 s each): no restarts 2/5 at best-known (A.1, A.3, A.4 one above);
/// 50,000: 4/5 (A.4 38 vs 37); 400,000: 3/5; a cycle 50k..400k: worse.
constexpr std::int64_t kRestartIterations = 50000;

class RowWeighting {
 public:
  RowWeighting(const Instance& inst, std::uint64_t seed)
      : inst_(inst),
        rng_(seed),
        cover_(static_cast<std::size_t>(inst.num_rows()), 0),
        weight_(static_cast<std::size_t>(inst.num_rows()), 1),
        uncovered_pos_(static_cast<std::size_t>(inst.num_rows()), -1),
        in_sol_(static_cast<std::size_t>(inst.num_cols()), 0),
        sol_pos_(static_cast<std::size_t>(inst.num_cols()), -1),
        score_(static_cast<std::size_t>(inst.num_cols()), 0),
        stamp_(static_cast<std::size_t>(inst.num_cols()), 0),
        can_add_(static_cast<std::size_t>(inst.num_cols()), 1) {
    for (std::int32_t i = 0; i < inst.num_rows(); ++i) push_uncovered(i);
    for (std::int32_t j = 0; j < inst.num_cols(); ++j) {
      score_[j] = static_cast<std::int64_t>(inst.column(j).size());
    }
  }

  /// Adds column k. `touch`: configuration checking marks its neighbours addable, which a
  /// (re)start's adds may skip: they start from every column addable and remove none.
  void add(std::int32_t k, bool touch = true) {
    for (std::int32_t i : inst_.column(k)) {
      if (cover_[i] == 0) {
        for (std::int32_t l : inst_.row(i)) {
          score_[l] -= weight_[i];
          if (kRowConfiguration) can_add_[l] = 1;
        }
        score_[k] += weight_[i];
        pop_uncovered(i);
      } else if (cover_[i] == 1) {
        score_[sole_cover(i, k)] += weight_[i];
      }
      ++cover_[i];
    }
    score_[k] = -score_[k];
    in_sol_[k] = 1;
    sol_pos_[k] = static_cast<std::int32_t>(sol_.size());
    sol_.push_back(k);
    cost_ += inst_.cost(k);
    if (touch) touch_neighbours(k);
  }

  void remove(std::int32_t j) {
    for (std::int32_t i : inst_.column(j)) {
      --cover_[i];
      if (cover_[i] == 0) {
        for (std::int32_t l : inst_.row(i)) {
          score_[l] += weight_[i];
          if (kRowConfiguration) can_add_[l] = 1;
        }
        score_[j] -= weight_[i];
        push_uncovered(i);
      } else if (cover_[i] == 1) {
        score_[sole_cover(i, j)] -= weight_[i];
      }
    }
    score_[j] = -score_[j];
    in_sol_[j] = 0;
    const std::int32_t p = sol_pos_[j];
    sol_[p] = sol_.back();
    sol_pos_[sol_[p]] = p;
    sol_.pop_back();
    sol_pos_[j] = -1;
    cost_ -= inst_.cost(j);
    touch_neighbours(j);
    can_add_[j] = 0;
  }

  /// Column of the solution to remove: largest score / cost (smallest loss per unit cost),
  /// ties to the oldest. Large solutions are sampled (best of kSample) to stay O(1).
  std::int32_t pick_removal(std::int32_t tabu) {
    std::int32_t best = -1;
    auto better = [&](std::int32_t a, std::int32_t b) {
      const double ra = static_cast<double>(score_[a]) / inst_.cost(a);
      const double rb = static_cast<double>(score_[b]) / inst_.cost(b);
      return ra > rb || (ra == rb && stamp_[a] < stamp_[b]);
    };
    const std::size_t n = sol_.size();
    constexpr std::size_t kSample = 64;
    if (n <= 4 * kSample) {
      for (std::int32_t j : sol_) {
        if (j != tabu && (best < 0 || better(j, best))) best = j;
      }
    } else {
      // The sample drawn first and its columns' scores and stamps asked for before they
      // are compared (they lie anywhere in arrays over all columns); the same draws and
      // comparisons, in the same order. One thread, 5·10^5 torus samples, 2 pinned pairs:
      // local search 0.150 / 0.154 -> 0.137 / 0.132 s.
      std::int32_t sample[kSample];
      for (std::size_t t = 0; t < kSample; ++t) sample[t] = sol_[rng_() % n];
      for (const std::int32_t j : sample) {
        __builtin_prefetch(&score_[j]);
        __builtin_prefetch(&stamp_[j]);
      }
      for (const std::int32_t j : sample) {
        if (j != tabu && (best < 0 || better(j, best))) best = j;
      }
      if (best < 0) return pick_removal_scan(tabu, better);
    }
    return best;
  }

  template <class Better>
  std::int32_t pick_removal_scan(std::int32_t tabu, Better better) const {
    std::int32_t best = -1;
    for (std::int32_t j : sol_) {
      if (j != tabu && (best < 0 || better(j, best))) best = j;
    }
    return best;
  }

  /// Column to add for a random uncovered row: largest score / cost among those allowed by
  /// configuration checking (all, if none is), ties to the oldest.
  std::int32_t pick_addition() {
    const std::int32_t r = uncovered_[rng_() % uncovered_.size()];
    std::int32_t best = -1;
    bool best_allowed = false;
    double best_ratio = 0.0;
    for (std::int32_t k : inst_.row(r)) {
      const double ratio = static_cast<double>(score_[k]) / inst_.cost(k);
      const bool allowed = can_add_[k] != 0;
      if (best < 0 || (allowed && !best_allowed) ||
          (allowed == best_allowed &&
           (ratio > best_ratio || (ratio == best_ratio && stamp_[k] < stamp_[best])))) {
        best = k;
        best_allowed = allowed;
        best_ratio = ratio;
      }
    }
    return best;
  }

  void bump_weights() {
    for (std::int32_t i : uncovered_) {
      ++weight_[i];
      for (std::int32_t l : inst_.row(i)) ++score_[l];
    }
  }

  /// Recomputes coverage counts and scores from scratch and compares (expensive check).
  bool is_valid() const {
    for (std::int32_t i = 0; i < inst_.num_rows(); ++i) {
      std::int32_t c = 0;
      for (std::int32_t l : inst_.row(i)) c += in_sol_[l];
      if (c != cover_[i] || (c == 0) != (uncovered_pos_[i] >= 0)) return false;
    }
    for (std::int32_t j = 0; j < inst_.num_cols(); ++j) {
      std::int64_t sc = 0;
      for (std::int32_t i : inst_.column(j)) {
        if (in_sol_[j] && cover_[i] == 1) sc -= weight_[i];
        if (!in_sol_[j] && cover_[i] == 0) sc += weight_[i];
      }
      if (sc != score_[j]) return false;
    }
    return true;
  }

  double exact_cost() const {
    double c = 0.0;
    for (std::int32_t j : sol_) c += inst_.cost(j);
    return c;
  }

  const Instance& inst_;
  std::mt19937_64 rng_;
  std::vector<std::int32_t> cover_;
  std::vector<std::int64_t> weight_;
  std::vector<std::int32_t> uncovered_;
  std::vector<std::int32_t> uncovered_pos_;
  std::vector<char> in_sol_;
  std::vector<std::int32_t> sol_;
  std::vector<std::int32_t> sol_pos_;
  std::vector<std::int64_t> score_;
  std::vector<std::int64_t> stamp_;
  std::vector<char> can_add_;
  double cost_ = 0.0;

 private:
  std::int32_t sole_cover(std::int32_t i, std::int32_t except) const {
    for (std::int32_t l : inst_.row(i)) {
      if (l != except && in_sol_[l]) return l;
    }
    RSTRUCT_ASSERT_MSG(false, "local search: coverage count out of sync");
  }
  void touch_neighbours(std::int32_t j) {
    if (kRowConfiguration) return;
    for (std::int32_t i : inst_.column(j)) {
      for (std::int32_t l : inst_.row(i)) can_add_[l] = 1;
    }
  }
  void push_uncovered(std::int32_t i) {
    uncovered_pos_[i] = static_cast<std::int32_t>(uncovered_.size());
    uncovered_.push_back(i);
  }
  void pop_uncovered(std::int32_t i) {
    const std::int32_t p = uncovered_pos_[i];
    uncovered_[p] = uncovered_.back();
    uncovered_pos_[uncovered_[p]] = p;
    uncovered_.pop_back();
    uncovered_pos_[i] = -1;
  }
};

}  // namespace

LocalSearchResult row_weighting_search(const Instance& inst, const std::vector<std::int32_t>& start,
                                       double start_cost, const LocalSearchOptions& options,
                                       const Stopwatch& clock) {
  LocalSearchResult result;
  result.best_cost = start_cost;
  if (inst.num_rows() == 0) {
    result.best_cost = 0.0;
    return result;
  }
  std::optional<RowWeighting> state;
  std::uint64_t restarts = 0;
  // (Re)start: fresh unit weights, a new random stream, from the best cover so far.
  auto restart = [&](const std::vector<std::int32_t>& from) {
    state.emplace(inst, options.seed + 0x9e3779b97f4a7c15ULL * restarts++);
    for (std::int32_t j : from) {
      if (!state->in_sol_[j]) state->add(j, /*touch=*/false);
    }
  };
  restart(start);
  const double slack = inst.has_integer_costs() ? 0.5 : 1e-9 * std::max(1.0, std::abs(start_cost));
  // With integer costs whose total is at most 2^53, every sum of some of them is an exact
  // double: the running cost then equals the sum over the solution, and each cover found
  // costs O(1) to price instead of O(solution). The sum had taken nine tenths of the local
  // search: 50,000 columns after nearly every iteration on 5·10^5 torus samples (one
  // thread, 2 pinned pairs, local search 0.55 / 0.57 -> 0.18 / 0.13 s, the same output).
  const bool running_cost_exact = [&] {
    if (!inst.has_integer_costs()) return false;
    double total = 0.0;
    for (const double c : inst.costs()) total += c;
    return total <= 0x1p53;
  }();
  std::int32_t tabu = -1;
  std::int64_t it = 0;
  const bool remove_first = inst.is_unicost();
  std::int64_t last_improvement = 0;
  while (true) {
    RowWeighting& s = *state;
    if (s.uncovered_.empty()) {
      const double c = running_cost_exact ? s.cost_ : s.exact_cost();
      if constexpr (check_level() >= 2) {
        RSTRUCT_ASSERT_MSG(!running_cost_exact || c == s.exact_cost(),
                           "local search: running cost out of sync");
      }
      if (c < result.best_cost - slack || (result.best.empty() && c <= result.best_cost + slack)) {
        result.best = s.sol_;
        result.best_cost = c;
        result.seconds_to_best = clock.seconds();
        last_improvement = it;
        if (c <= options.target + slack) {
          if (options.stop != nullptr) options.stop->store(true, std::memory_order_relaxed);
          break;
        }
      }
      s.remove(s.pick_removal(-1));
      continue;
    }
    if (it >= options.max_iterations) {
      result.hit_iteration_limit = true;
      break;
    }
    ++it;
    if ((it & 63) == 0) {
      if (clock.seconds() > options.deadline) {
        result.timed_out = true;
        break;
      }
      if (options.stop != nullptr && options.stop->load(std::memory_order_relaxed)) break;
    }
    if (it - last_improvement > kRestartIterations && !result.best.empty()) {
      last_improvement = it;
      restart(result.best);
      continue;
    }
    // Unicost: RWLS's order, drop one column and then repair. Weighted: add first and then
    // drop the worst columns until cheaper than the best (a swap move, better there).
    if (remove_first && s.sol_.size() > 1) {
      const std::int32_t j = s.pick_removal(tabu);
      s.remove(j);
      s.stamp_[j] = it;
    }
    const std::int32_t k = s.pick_addition();
    s.add(k);
    s.stamp_[k] = it;
    tabu = k;
    while (s.cost_ >= result.best_cost - slack && s.sol_.size() > 1) {
      const std::int32_t j = s.pick_removal(tabu);
      s.remove(j);
      s.stamp_[j] = it;
    }
    s.bump_weights();
    if constexpr (check_level() >= 3) RSTRUCT_ASSERT_MSG(s.is_valid(), "local search state out of sync");
  }
  result.iterations = it;
  return result;
}

}  // namespace rstruct::setcover::detail
