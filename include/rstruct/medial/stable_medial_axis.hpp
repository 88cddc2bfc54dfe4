#pragma once
/// \file
/// Stable medial axis from an r-sample (paper §3 "Medial axis approximation", §5.1, Table 2;
/// issue 8): the inner polar balls DMAT_in enlarged by ε (DMAT'_in), a small subset
/// DMAT''_in of them that still covers every sample (set cover with a certified bound), and
/// the exact medial axis of the union of DMAT''_in (medial_axis.hpp).
///
/// The §5.1 check: DMAT'_in must stay clear of A_out (the α-shape of the outer polar balls).
/// We test its vertices, the outer poles: an outer pole whose centre lies in an enlarged
/// inner ball (exact side_of_ball) is a violation. Poles of tetrahedra with a bounding-box
/// site stand for poles at infinity and are not tested (their count is reported).

#include <cstdint>
#include <span>
#include <vector>

#include "rstruct/geometry/vec3.hpp"
#include "rstruct/medial/medial_axis.hpp"
#include "rstruct/pipeline/prune_balls.hpp"

namespace rstruct {
class Report;
}

namespace rstruct::medial {

struct StableMedialAxisOptions {
  /// Absolute enlargement ε of the inner polar balls; negative: use eps_rel.
  double eps = -1.0;
  /// ε relative to the samples' bounding-box diagonal (used when eps < 0).
  double eps_rel = 0.005;
  /// Set-cover time limit in seconds; negative: automatic, proportional to the instance
  /// (0.05 s + 10 ms per thousand rows, at most 1.5 s). The set cover runs on every k-th
  /// sample (k ≈ (1 + ε / spacing)²); the samples its cover misses are then covered by a
  /// second, small set cover, so the kept balls cover every sample and the certified bound
  /// (of the subset, hence of the whole instance) stays valid.
  double cover_time_limit = -1.0;
  std::uint64_t seed = 1;
  unsigned threads = 0;  ///< 0: all cores
  /// Run the §5.1 check (one more covering pass: outer poles against DMAT'_in).
  bool check_outer_poles = true;
};

struct StableMedialAxis {
  double eps = 0;                     ///< the absolute ε used
  double bbox_diagonal = 0;
  std::size_t samples = 0;
  std::size_t inner_poles = 0;        ///< |DMAT_in|
  std::size_t outer_poles = 0;        ///< outer poles tested by the §5.1 check
  std::size_t box_poles = 0;          ///< outer poles at infinity (box sites), not tested
  std::size_t violations = 0;         ///< outer poles inside some ball of DMAT'_in
  std::vector<Ball> polar_balls;      ///< DMAT'_in (enlarged)
  std::vector<std::uint32_t> kept;    ///< indices into polar_balls: DMAT''_in
  std::vector<Ball> kept_balls;       ///< DMAT''_in
  pipeline::PruneResult prune;
  double cover_time_limit = 0;        ///< the limit used (last round)
  std::size_t cover_rows = 0;         ///< samples that were rows of the set cover
  std::size_t repaired_samples = 0;   ///< samples the cover missed, covered by a second cover
  MedialAxis axis;
  MedialAxisStats axis_stats;
  complex::BettiNumbers betti_axis;
  // Seconds per stage (Table 2).
  double polar_seconds = 0;           ///< Delaunay, poles, labels
  double pruning_seconds = 0;         ///< enlargement, covering sets, set cover
  double check_seconds = 0;           ///< §5.1 check
  double medial_seconds = 0;          ///< medial axis of DMAT''_in (+ its homology)
};

/// \throws InvalidInput as poles::analyse_poles (fewer than 4 samples, non-finite
///   coordinates), or if ε is negative or not finite.
/// \throws ComputationFailed if no pole is labelled inner.
StableMedialAxis stable_medial_axis(std::span<const Point3> samples,
                                    const StableMedialAxisOptions& options = {},
                                    Report* report = nullptr);

/// The medial axis step alone, for a given union of balls, with the same report stages.
StableMedialAxis medial_axis_of_balls(std::span<const Ball> balls, Report* report = nullptr);

}  // namespace rstruct::medial
