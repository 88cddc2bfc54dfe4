#pragma once
/// \file
/// Near-optimal set cover with a certified lower bound (paper §6; issue 6).
///
/// Pipeline: reduction (zero-cost and forced columns, dominated rows and columns,
/// connected components) → greedy with lazy updates → Lagrangian subgradient optimisation
/// on a core of columns with re-pricing and Lagrangian greedy heuristics (Caprara, Fischetti,
/// Toth 1999) → reduced-cost fixing → row-weighting local search (Gao, Weise, Li 2015,
/// extended to weighted costs). The lower bound is L(u) for the best multipliers found,
/// evaluated exactly over every column of the original instance.

#include <cstdint>
#include <vector>

#include "rstruct/setcover/certificate.hpp"
#include "rstruct/setcover/instance.hpp"

namespace rstruct::setcover {

/// Every stage stops on work as well as on time: reduction after two domination passes or
/// a number of entries scanned (`domination_work_per_entry` times the instance's entries,
/// at most `max_domination_work`), whichever is first,
/// coordinate ascent after a fixed number of sweeps, the subgradient after
/// `max_subgradient_iterations` (or when it stalls), the exact search on small components
/// after 300,000 nodes, the local search after `max_local_search_iterations`. Only the local
/// search has no work limit by default; with one, and a time limit generous enough never to
/// be reached (SolverStats::stopped_by says whether it was), the result depends on the
/// instance, `seed` and these limits only, not on the machine, its load or `threads`.
struct SolverOptions {
  /// Wall-clock budget in seconds (anytime: the best cover so far is returned). Shared
  /// among the components in proportion to their entries; within a component the
  /// coordinate ascent may use 20 % of it, the subgradient 30 % of the rest.
  double time_limit = 10.0;
  /// Seed of every random choice. With a fixed seed the result is deterministic as long as
  /// the work limits below, not the time limit, end the search.
  std::uint64_t seed = 1;
  /// Local-search iterations per stream over all components (0: no limit besides time),
  /// shared among the components in proportion to their entries (the shares add up to
  /// exactly this number; a tiny component may get none).
  std::int64_t max_local_search_iterations = 0;
  /// Subgradient iterations per component.
  std::int32_t max_subgradient_iterations = 10000;
  /// Presolve with row and column domination (forced columns are always taken).
  bool use_domination = true;
  /// Work limit of the domination passes: entries scanned, per entry of the instance
  /// (0: none besides time). Domination costs up to the sum over entries of the pivot's
  /// line length, quadratic in the density: on 10^6 samples of a torus with large shrunk
  /// balls (level 2 of bench_seed --torus) the passes ran past the time cap, 93 s, and
  /// their result depended on the machine's speed. Measured without a limit: the double
  /// torus levels of bench_seed take 15 and 21 per entry, OR-Library's instances (weighted
  /// and unicost) at most 29.7, so 64 leaves all of them unchanged.
  double domination_work_per_entry = 64;
  /// And at most this many entries scanned in all (0: no such cap). At 64 per entry the
  /// torus instance above (1.4 × 10^8 entries) still took 81 s, about 1.1 × 10^8 entries
  /// scanned per second; 10^9 bounds the passes at about 9 s on this machine and is 7 times
  /// the largest double-torus level's need.
  std::int64_t max_domination_work = 1'000'000'000;
  /// Independent local-search streams per component (seeds derived from `seed` and the
  /// stream index; the best cover wins, ties to the lower index). A fixed number, so that
  /// iteration-limited runs give the same result on any machine; each stream gets the
  /// whole local-search iteration budget. Measured on OR-Library's unicost A.4 (10 s):
  /// one stream with seed 1 stays at 38, seeds 2-5 find the best-known 37; two streams
  /// with seed 1 reach all 30 unicost best-known values of families 4, 5, 6 and A.
  std::int32_t local_search_streams = 2;
  /// Threads (0: hardware concurrency): for the streams, and on large components for the
  /// pricing passes and the greedy beside the first ascent (the result is the same for any
  /// count). With fewer threads than streams the streams run one after another, each with
  /// its share of the time.
  unsigned threads = 0;
};

/// Which kind of limit ended a search (SolverStats::stopped_by).
enum class SearchLimit : std::uint8_t {
  kNone,        ///< every stage ended on its own: gap closed, exact search done, stalled
  kIterations,  ///< no stage was cut by time; an iteration or node limit ended one or more
  kTime,        ///< the time limit cut some stage short: the result depends on the machine
};

/// "none", "iterations" or "time".
const char* to_string(SearchLimit limit);

/// Counters for reports.
struct SolverStats {
  double seconds = 0.0;
  double seconds_to_best = 0.0;  ///< when the returned cover was found
  double greedy_cost = 0.0;      ///< Chvátal greedy on the reduced instance (+ fixed part)
  std::int64_t forced_columns = 0;
  std::int64_t dominated_rows = 0;
  std::int64_t dominated_columns = 0;
  std::int64_t components = 0;
  std::int64_t subgradient_iterations = 0;   ///< over all components
  /// Over all components and streams: at most local_search_streams ×
  /// max_local_search_iterations when that is positive.
  std::int64_t local_search_iterations = 0;
  std::int64_t exact_nodes = 0;  ///< branch-and-bound nodes over all components
  SearchLimit stopped_by = SearchLimit::kNone;
  double reduction_seconds = 0.0;
  std::int64_t reduction_work = 0;  ///< entries scanned by the domination passes
  double greedy_seconds = 0.0;
  double subgradient_seconds = 0.0;
  double local_search_seconds = 0.0;
  double certificate_seconds = 0.0;
};

struct Solution {
  std::vector<std::int32_t> columns;  ///< chosen columns, sorted, 0-based
  double cost = 0.0;
  /// Certified lower bound: the certificate's L(u), computed exactly over all columns and
  /// rounded down (rounded up to an integer first when all costs are integers).
  double lower_bound = 0.0;
  /// (cost − lower_bound) / cost, 0 when cost is 0.
  double gap = 0.0;
  /// True when lower_bound == cost: the cover is proven optimal by the certificate.
  bool optimal = false;
  /// True when no cheaper cover exists: `optimal`, or a proof the certificate cannot carry
  /// (reduced-cost fixing left some row without a column, or the exact search finished).
  bool proven_optimal = false;
  Certificate certificate;
  SolverStats stats;
};

/// Solves `inst`. \throws ComputationFailed if some row is covered by no column (the
/// message names the row, 0-based).
Solution solve(const Instance& inst, const SolverOptions& options = {});

}  // namespace rstruct::setcover
