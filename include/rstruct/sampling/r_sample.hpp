#pragma once
/// \file
/// Certified r-samples (paper, Definition 1: S ⊂ F is an r-sample if every x ∈ F has a
/// point of S within r·lfs(x); DESIGN.md §8).
///
/// **Certification** (certify_r_sample). The parameter domain of the surface's charts is
/// covered by rectangular cells, refined adaptively (binary splits along the direction of
/// larger 3-D reach). For a cell with centre image g, radius ρ (Surface::cell_reach: every
/// point of F in the cell is within ρ of the computed g, rounding included) and d = dist(g,
/// S) from a kd-tree (nanoflann), l = lfs(g):
///   every x ∈ F in the cell has dist(x, S) ≤ d + ρ and lfs(x) ≥ l − ρ,
/// because both dist(·, S) and lfs = dist(·, medial axis) are 1-Lipschitz on R³. Hence
///   sup over the cell of dist(x, S)/lfs(x) ≤ (d + ρ)/(l − ρ)   (when ρ < l).
/// A cell is accepted when this bound (times 1 + 1e-12 for the rounding of d, l and the
/// division) is ≤ the threshold; otherwise it is split, unless d/l itself exceeds the
/// threshold (a violation: g is a point of F, up to rounding, that S does not cover). The
/// reported upper_bound is the largest accepted bound: what is proven is
///   sup_{x ∈ F} dist(x, S) / lfs(x) ≤ upper_bound,
/// assuming (i) the medial-axis formulas of the surface (DESIGN.md §8; checked by tests
/// against brute force, not proven here), (ii) lfs() accurate to 1e-12 relative, and
/// (iii) the cell-reach bounds (derivative bounds of each parametrization, in the classes'
/// comments). grid_max (largest d/l over all cell centres) is an achieved value, so the
/// true supremum lies in [grid_max, upper_bound]. The grid is as dense as needed: a cell
/// is accepted only when ρ/l ≤ (threshold − d/l)/(1 + threshold), so cells are finest
/// where S is sparsest; leaf-cell reach statistics are reported.
///
/// **Generation** (generate_r_sample). A jittered initial sample (one random point per
/// cell of radius ≤ spacing·r_fill·lfs, r_fill = fill_fraction·r), then rounds of
/// certification at threshold r in which every uncertifiable cell centre with
/// d/l > r_fill becomes a new sample point (thinned so that new points are ≥ r_fill·l/2
/// apart), until a round certifies everything. Termination: each added point is at
/// distance > r_fill·lfs from the previous points, so by packing only finitely many can be
/// added; cells with d/l ≤ r_fill are accepted once ρ/l ≤ (r − r_fill)/(1 + r). Cells
/// accepted in one round stay accepted (adding points only lowers dist(·, S)), so later
/// rounds revisit only the previous round's violating cells. The final sample is then
/// certified afresh by certify_r_sample at threshold r (its own full pass), and the bound
/// is tightened by certifying at 1.05 × the largest ratio seen so far (up to 4 attempts,
/// each failed attempt raising that ratio); the tightest success is reported.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "rstruct/sampling/surface.hpp"

namespace rstruct::sampling {

struct CertifyOptions {
  /// Each chart starts as n × n cells.
  int initial_cells_per_side = 4;
  /// Deepest binary subdivision; a cell needing more is "undecided" (not certified).
  int max_depth = 64;
};

struct Certificate {
  double threshold = 0;         ///< the r certified against
  bool certified = false;       ///< every cell accepted: sup dist/lfs ≤ upper_bound ≤ threshold
  double upper_bound = 0;       ///< proven bound on sup_{x∈F} dist(x, S)/lfs(x) (if certified)
  double grid_max = 0;          ///< max of dist/lfs over the cell centres visited (achieved)
  std::size_t grid_points = 0;  ///< cell centres evaluated
  std::size_t leaf_cells = 0;   ///< accepted cells
  double max_leaf_reach_over_lfs = 0;  ///< coarsest accepted cell, ρ/lfs
  double min_leaf_reach_over_lfs = 0;  ///< finest accepted cell, ρ/lfs
  /// When not certified: a cell centre with dist/lfs > threshold, or a cell that could not
  /// be decided within max_depth splits.
  std::optional<Point3> violation;
  double violation_ratio = 0;
  bool undecided = false;
  double seconds = 0;
};

/// Certifies (or refutes) that `samples` is an r-sample of `surface` (see the file comment).
/// \throws InvalidInput if the surface has no parametrization or unknown lfs, r is not in
/// (0, 1], or a sample is not finite.
Certificate certify_r_sample(const Surface& surface, const std::vector<Point3>& samples, double r,
                             const CertifyOptions& options = {});

struct RSampleOptions {
  std::uint64_t seed = 1;
  /// r_fill = fill_fraction · r: cell centres farther than r_fill·lfs from S get a point.
  double fill_fraction = 0.8;
  /// Initial jittered sample: one point per cell of radius ≤ spacing · r_fill · lfs.
  double spacing = 1.4;
  int max_rounds = 100;
  /// Refuse (InvalidInput) when the initial sample alone would exceed this many points
  /// (predicted from a coarse pass first: requests needing over ~2× this fail fast).
  std::size_t max_points = 5000000;
  /// Re-certify at thresholds just above grid_max to report a tighter upper bound.
  bool tighten = true;
  CertifyOptions certify;
};

struct RSample {
  double requested_r = 0;
  std::vector<Point3> points;
  Certificate certificate;  ///< the tightest successful certification
  std::size_t initial_points = 0;
  std::size_t added_points = 0;
  int rounds = 0;
  double generation_seconds = 0;     ///< initial sample + filling rounds
  double certification_seconds = 0;  ///< tightening passes
};

/// An lfs-adaptive r-sample of `surface` with a certificate: certificate.certified and
/// certificate.upper_bound ≤ r on return.
/// \throws InvalidInput as certify_r_sample, or for options out of range or an r so small
/// that more than max_points points would be needed; ComputationFailed if max_rounds
/// rounds do not suffice.
RSample generate_r_sample(const Surface& surface, double r, const RSampleOptions& options = {});

}  // namespace rstruct::sampling
