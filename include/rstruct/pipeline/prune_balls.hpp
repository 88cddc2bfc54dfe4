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

namespace rstruct {
class Report;
}

namespace rstruct::pipeline {

struct PruneOptions {
  double time_limit = 1.0;  ///< seconds for the set-cover solver (anytime)
  std::uint64_t seed = 1;
  unsigned threads = 0;     ///< covering sets (0: all cores)
};

struct PruneResult {
  std::vector<std::uint32_t> kept;  ///< indices of kept candidates, increasing
  std::size_t entries = 0;          ///< non-zeros of the covering matrix
  double cost = 0;                  ///< cover size (unicost)
  double lower_bound = 0;           ///< certified lower bound on the optimum
  double gap = 0;                   ///< (cost − bound) / cost
  bool optimal = false;
  double seconds = 0;
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
