#pragma once
/// \file
/// Pruning by set cover (paper §6, Theorem 6.1; DESIGN.md §2–§3): keep a small subset of
/// candidate balls whose *shrunk* copies still cover every sample. Columns are the shrunk
/// balls (one per candidate), rows the samples; the cover comes with a certified lower
/// bound from the set-cover module, so every report states cost, bound and gap.

#include <cstdint>
#include <span>
#include <vector>

#include "rstruct/geometry/vec3.hpp"
#include "rstruct/setcover/solver.hpp"

namespace rstruct {
class Report;
}

namespace rstruct::pipeline {

/// Default work budget of the set cover (PruneOptions::iterations), calibrated on the demo's
/// double torus against the former 0.3 s wall-clock limit (bench_seed, 2 cores, loaded,
/// medians of 3). Level 3 (ρ̃ = 0.5): 0.22 s against 0.30 s, cover 487 (gap 31.4 %) against
/// 484–502 (29–32 %). Level 2 (ρ̃ = 0.15) cannot be as fast: its reduction alone takes
/// 0.25–0.3 s, which the 0.3 s limit cut short, leaving no time for the subgradient or the
/// local search (cover 4755–4765, gap 36–38 %); with the budget it takes 0.8–0.9 s, cover
/// 4600 (gap 28.8 %). Halving the budget saves about 0.15 s there and costs level 3 about
/// 15–25 balls.
inline constexpr std::int64_t kDefaultCoverIterations = 10000;
/// Default subgradient iterations per component with a work budget. On level 2 an iteration
/// costs about 7 ms; the first 20 did not raise the bound that coordinate ascent reached,
/// 100 raised it by 2.5 % at 0.6 s more.
inline constexpr std::int32_t kDefaultCoverSubgradientIterations = 10;
/// Default wall-clock cap of the set cover: a safety net that a work-limited search on
/// the demo's inputs never reaches.
inline constexpr double kDefaultCoverTimeCap = 60.0;

struct PruneOptions {
  /// Work budget of the set cover: local-search iterations per search stream, shared by
  /// the components (setcover::SolverOptions::max_local_search_iterations). With it the kept
  /// set depends only on the balls, the points, `seed` and this budget, not on the
  /// machine, its load or `threads` — unless `time_limit` ends the search first, which
  /// PruneResult::solver.stopped_by reports. 0: no work limit; the time limit alone ends the
  /// search (anytime, machine-dependent).
  std::int64_t iterations = kDefaultCoverIterations;
  /// Subgradient iterations per component when `iterations` > 0
  /// (setcover::SolverOptions::max_subgradient_iterations); with `iterations` = 0 the
  /// solver's own default applies, as before work budgets existed.
  std::int32_t subgradient_iterations = kDefaultCoverSubgradientIterations;
  /// Wall-clock limit of the set cover in seconds: with `iterations` a safety cap, without
  /// it the budget.
  double time_limit = kDefaultCoverTimeCap;
  std::uint64_t seed = 1;
  unsigned threads = 0;     ///< covering sets and local-search streams (0: all cores)
};

struct PruneResult {
  std::vector<std::uint32_t> kept;  ///< indices of kept candidates, increasing
  std::size_t entries = 0;          ///< non-zeros of the covering matrix
  double cost = 0;                  ///< cover size (unicost)
  double lower_bound = 0;           ///< certified lower bound on the optimum
  double gap = 0;                   ///< (cost − bound) / cost
  bool optimal = false;
  double seconds = 0;
  setcover::SolverOptions solver_options;  ///< the budget the solver ran with
  /// Iteration counts, stage seconds, and which limit ended the search (stopped_by).
  setcover::SolverStats solver;
};

/// Keeps a subset of `shrunk` (the candidates' shrunk balls, in candidate order) whose
/// union covers every point of `points`, minimising the number kept.
/// Stage seconds ("covering sets", "set cover") go to `report` when given.
/// \throws ComputationFailed if some point is covered by no shrunk ball (the message names
/// it; for surface balls every sample covers itself, so this only happens for medial
/// balls or radii of zero).
PruneResult prune_balls(std::span<const Ball> shrunk, std::span<const Point3> points,
                        const PruneOptions& options = {}, Report* report = nullptr);

}  // namespace rstruct::pipeline
