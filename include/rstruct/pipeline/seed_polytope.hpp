#pragma once
/// \file
/// The paper's main pipeline (§3, Figure 1; §5–§6; DESIGN.md §1–§5): from an r-sample S of
/// a closed surface F to the *seed polytope*, a triangle mesh whose vertices are a subset of
/// S, with the topology of F, plus the map from every sample to its polytope vertex.
///
///  1. Delaunay of S, poles, inner/outer labels, pole distance D̂ (poles module).
///  2. Surface balls B(s, ρ·D̂(s)); ρ ∈ [0.24, 0.56] carries Lemma 5.6's guarantee.
///  3. Pruning (ρ̃ > 0): a certified set cover of S by the shrunk balls B(u, ρ̃·D̂(u));
///     ρ̃ ≤ 0.03 carries Theorem 6.1's guarantee. ρ̃ = 0 keeps every ball.
///  4. Regular triangulation of the kept balls and their dual complex K (weighted α-shape
///     at α = 0), homotopy-equivalent to the union of the kept balls.
///  5. Free faces of K collapsed until none remain (homotopy type kept); the rest is the
///     output, reported with its Betti numbers over Z₂ and whether it is a closed
///     2-manifold — measured on the complex, never assumed.
///  6. Sample map: each sample goes to the kept ball whose power cell contains it; if that
///     ball is not a vertex of the output (its vertex was collapsed away), to the output
///     vertex whose power cell among the output vertices' balls contains it (counted in
///     `remapped_samples`). Both decisions are exact power comparisons, found by a
///     downhill walk in power distance over the triangulation's edges (a power cell is
///     cut out by its neighbours alone, so a vertex with no neighbour of smaller power
///     distance owns the sample), started from the sample's own ball when it is a vertex
///     and otherwise from the answer of the previous sample along a Hilbert curve.
///
/// With smaller ρ and ρ̃ the same pipeline is the paper's scalable reconstruction. Levels
/// of detail on the same samples share step 1: compute a PoleAnalysis once and call the
/// overload that takes it; a coarser level may restrict its pruning candidates to the
/// balls kept by a finer one (SeedOptions::candidates).

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "rstruct/complex/homology.hpp"
#include "rstruct/complex/manifold.hpp"
#include "rstruct/geometry/vec3.hpp"
#include "rstruct/pipeline/prune_balls.hpp"
#include "rstruct/poles/pole_analysis.hpp"

namespace rstruct {
class Report;
}

namespace rstruct::pipeline {

struct SeedOptions {
  double rho = 0.5;        ///< surface-ball factor ρ
  double rho_tilde = 0.03; ///< shrunk-ball factor ρ̃ (0: no pruning)
  PruneOptions prune;
  /// For the pole analysis of compute_seed_polytope(samples, options); its `label` is not
  /// used (the labels run beside the level when there is more than one thread).
  poles::PoleAnalysisOptions poles;
  /// Refuse to continue when the pole labeling is not clean (unlabelled or contradictory
  /// poles): D̂ uses poles of both labels, so labels do not enter the seed polytope, but
  /// a dirty labeling means the input is probably not an r-sample of a closed surface.
  bool require_clean_labels = false;
  /// Samples whose balls may be kept (strictly increasing sample ids); empty: every
  /// sample. Pruning (ρ̃ > 0) chooses among these; ρ̃ = 0 keeps all of them. Every sample
  /// must still be covered by some candidate's shrunk ball, which holds for the balls kept
  /// by a pruning with a smaller ρ̃ (nested levels of detail).
  std::vector<std::uint32_t> candidates;
  /// Threads for the parallel stages (0: hardware concurrency). Results do not depend on it.
  unsigned threads = 0;
};

struct SeedPolytope {
  /// Output mesh: vertex k is sample `vertex_sample[k]`; triangles index these vertices,
  /// consistently oriented when the surface is orientable (outward if the signed volume
  /// allows telling).
  std::vector<std::uint32_t> vertex_sample;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  /// Output vertex of every input sample.
  std::vector<std::uint32_t> sample_vertex;
  std::size_t remapped_samples = 0;

  std::vector<std::uint32_t> kept;     ///< samples whose balls were kept (sorted)
  std::vector<double> dhat;            ///< D̂ per sample
  std::vector<double> radius;          ///< surface-ball radius ρ·D̂ per sample
  std::size_t hidden_balls = 0;        ///< kept balls with empty power cells
  triangulation::TriangulationStats triangulation;  ///< the kept balls' regular triangulation
  PruneResult prune;                   ///< cover size, certified bound and gap (if pruned)
  bool pruned = false;

  std::array<std::size_t, 4> k_counts{};      ///< simplices of K by dimension
  std::array<std::size_t, 4> facet_classes{};  ///< exterior, singular, regular, interior
  complex::BettiNumbers betti_k;
  complex::BettiNumbers betti_output;
  complex::ManifoldCheck manifold;
  bool oriented = false;                       ///< consistently oriented (orientable)

  poles::LabelingStats labeling;
  std::vector<std::string> warnings;           ///< parameter guards, labeling problems
};

/// Runs the pipeline. Stage seconds (wall and CPU) go to `report` (Table 1 breakdown:
/// "delaunay", "poles", "pole distance", "surface balls", "covering sets", "set cover",
/// "regular triangulation", "vertex stars", "dual complex", "collapse + homology",
/// "sample map", "labels (wait)"). The pole labels, which only the final check reads, are
/// computed on one more thread beside the stages after "pole distance" (see
/// PendingLabels); "labels (wait)" is the time the pipeline waited for them at the end.
/// \throws InvalidInput for bad parameters (NaN, negative, ρ̃ ≥ ρ, ρ > 1, candidates out of
/// range or not increasing) or inputs that the poles stage rejects; ComputationFailed if
/// require_clean_labels and the labeling is not clean, or if some sample is covered by no
/// candidate's shrunk ball.
SeedPolytope compute_seed_polytope(std::span<const Point3> samples, const SeedOptions& options,
                                   Report* report = nullptr);

/// The same from a PoleAnalysis of `samples` computed beforehand (options.poles is then
/// not used): levels of detail share the Delaunay triangulation, poles and D̂.
/// If the analysis was made without labels (PoleAnalysisOptions::label false), `pending`
/// must be the PendingLabels labelling it: the level runs beside the labelling, waits for
/// it at the end (stage "labels (wait)") and checks the labels then; the analysis is
/// labelled afterwards, so later levels need no `pending` (with a labelled analysis the
/// labels are checked first and `pending` is not used).
/// \pre `analysis` = poles::analyse_poles(samples, ...).
/// \throws as above; InvalidInput if the analysis has a different number of samples, or is
/// unlabelled and `pending` is null or labels another analysis.
SeedPolytope compute_seed_polytope(std::span<const Point3> samples,
                                   const poles::PoleAnalysis& analysis,
                                   const SeedOptions& options, Report* report = nullptr,
                                   poles::PendingLabels* pending = nullptr);

}  // namespace rstruct::pipeline
