#pragma once
// Lagrangian relaxation of set cover (Beasley 1990; Caprara, Fischetti, Toth 1999, "CFT"):
// for multipliers u >= 0, L(u) = Σ_i u_i + Σ_j min(0, c_j − Σ_{i∈S_j} u_i) is a lower bound.
// Subgradient optimisation on a core of columns with periodic re-pricing over all columns,
// with CFT's step-size control and Lagrangian greedy heuristics along the way.

#include <cstdint>
#include <exception>
#include <memory>
#include <span>
#include <thread>
#include <vector>

#include "rstruct/core/stopwatch.hpp"
#include "rstruct/setcover/instance.hpp"

namespace rstruct::setcover::detail {

/// L(u) over every column of `inst`, in floating point (the certified value is recomputed
/// exactly elsewhere). Fills `reduced` (size num_cols) with c_j − Σ_{i∈S_j} u_i if non-null.
/// With `threads` > 1 (0: hardware concurrency) large instances price their columns in
/// parallel; the value is the same double.
double lagrangian_bound(const Instance& inst, std::span<const double> u,
                        std::vector<double>* reduced = nullptr, unsigned threads = 1);

struct SubgradientOptions {
  std::int32_t max_iterations = 2000;
  double deadline = 1.0;  ///< seconds on `clock` after which to stop
  bool run_heuristics = true;
  unsigned threads = 1;  ///< for pricing and the core (0: hardware concurrency); same result
};

/// A Lagrangian greedy running on its own thread (see subgradient()).
struct PendingHeuristic {
  std::vector<std::int32_t> cover;
  std::exception_ptr error;
  std::jthread thread;  // declared last: joined before the cover goes
};

/// State shared with the caller: best multipliers (with a bound valid over all columns)
/// and best cover found so far (improved by the Lagrangian greedy).
struct LagrangianState {
  std::vector<double> u;
  double bound = 0.0;
  std::vector<std::int32_t> cover;
  double cover_cost = 0.0;
  std::int64_t iterations = 0;
  std::int64_t heuristic_calls = 0;
  bool timed_out = false;            ///< a deadline ended coordinate ascent or the subgradient
  bool hit_iteration_limit = false;  ///< the subgradient ran all its max_iterations
  /// The greedy of the subgradient's last iteration, when it runs beside the caller's next
  /// steps; finish_heuristic() takes its cover. Null otherwise.
  std::unique_ptr<PendingHeuristic> pending;
};

/// Initial multipliers u_i = min_{j ∋ i} c_j / |S_j|.
std::vector<double> initial_multipliers(const Instance& inst);

/// True when `bound` proves `cost` optimal (integer costs: ⌈bound⌉ >= cost).
bool bound_closes_gap(const Instance& inst, double bound, double cost);

/// Block-free coordinate ascent on L: for each row i in turn (fewest columns first), L as a
/// function of u_i alone is concave piecewise linear with slope 1 − #{j ∋ i : a_j < u_i},
/// a_j = c_j − Σ_{k∈S_j, k≠i} u_k, so it is maximal for u_i between the two smallest a_j;
/// u_i takes the smallest (keeping row i's columns at reduced cost ≥ 0). L never decreases.
/// One sweep costs O(entries). Updates state.u / state.bound if the bound improves.
/// `threads` prices the columns after each sweep (the same result for any count).
void coordinate_ascent(const Instance& inst, LagrangianState& state, std::int32_t sweeps,
                       double deadline, const Stopwatch& clock, unsigned threads = 1);

/// Runs subgradient optimisation from state.u, updating state in place.
/// \pre state.cover is a cover of inst with cost state.cover_cost.
/// On a large instance with several threads, the Lagrangian greedy of the last iteration
/// (it == max_iterations) is left running in state.pending: the caller may improve the
/// multipliers meanwhile, and must call finish_heuristic() before it reads the cover.
void subgradient(const Instance& inst, LagrangianState& state, const SubgradientOptions& options,
                 const Stopwatch& clock);

/// Waits for state.pending (if any) and keeps its cover if it is cheaper; rethrows its
/// exception.
void finish_heuristic(const Instance& inst, LagrangianState& state);

}  // namespace rstruct::setcover::detail
