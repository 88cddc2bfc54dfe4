#pragma once
/// \file
/// Inner/outer labeling of the poles of a closed surface's r-sample: the greedy propagation
/// of the power crust (Amenta, Choi, Kolluri 2001, §5 "labeling the poles"; DESIGN.md §1).
///
/// Which pairs are compared. Two poles are compared when their polar spheres pass through a
/// common sample s, i.e. both Delaunay tetrahedra have s as a vertex ("poles whose Delaunay
/// cells share a vertex"). This includes the two poles of one sample. For such a pair the
/// angle of intersection of the two spheres, measured at their common point s, is
/// φ = ∠(p − s, q − s), so cos φ = (r₁² + r₂² − d²)/(2r₁r₂) is evaluated at s directly.
/// For an r-sample, Lemma 4.3(a) of the paper puts both centres within about 3r of the
/// surface normal line at s (on their own sides), so poles on the same side meet at
/// φ ≲ 6r (deep intersection, cos φ near 1) and poles on opposite sides at φ ≳ π − 6r
/// (cos φ near −1): the evidence is unambiguous for r ≤ 0.08.
///  - "same" evidence, weight cos φ, if cos φ ≥ same_min_cos (deep intersection);
///  - "opposite" evidence, weight −cos φ, if −cos φ ≥ opposite_min_cos (for the two poles
///    of one sample this is −cos ∠p⁺ s p⁻, the power crust's opposite-pole weight).
///
/// Propagation. Every pole keeps the largest inner and outer evidence received so far.
/// Poles whose tetrahedron has a bounding-box site are outer (their centre lies outside
/// the samples' bounding box, hence outside the solid) and seed a max-priority queue with
/// weight 2 (above any cosine). Repeatedly the unlabelled pole with the largest evidence is
/// labelled with the side of that evidence, and passes evidence to every pole it is compared
/// with (labelled or not, so that contradictions are seen).
///
/// Computed by a breadth-first two-colouring from the box poles wherever that gives the same
/// labels and counts, i.e. when no evidence contradicts the colouring (then the greedy's
/// result is the one colouring that every piece of evidence agrees with); at the first
/// contradiction, by the greedy itself (src/poles/pole_labeling.cpp).
///
/// Failures are reported, never guessed: a pole no evidence reaches stays unlabelled; a pole
/// with equal inner and outer evidence stays unlabelled (a tie); a labelled pole that also
/// received evidence for the other side is counted as contradictory; a sample whose two
/// poles received the same label is counted as inconsistent.

#include <cstddef>

#include "rstruct/poles/pole_set.hpp"

namespace rstruct::poles {

struct LabelingParameters {
  /// Deep intersection: cos φ at least this gives "same side" evidence (default: φ ≤ 60°).
  double same_min_cos = 0.5;
  /// Opposite sides: −cos φ at least this gives "opposite" evidence (default: φ ≥ 120°).
  double opposite_min_cos = 0.5;
};

struct LabelingStats {
  std::size_t inner = 0;
  std::size_t outer = 0;
  std::size_t unlabelled = 0;          ///< no evidence reached them, or ties
  std::size_t ties = 0;                ///< of which: equal inner and outer evidence
  std::size_t contradictory = 0;       ///< labelled, but with evidence for the other side too
  std::size_t inconsistent_samples = 0;///< samples whose two poles got the same label
  std::size_t samples_without_inner = 0; ///< samples with no pole labelled inner
  std::size_t pairs_examined = 0;      ///< (pole, pole) comparisons made

  bool operator==(const LabelingStats&) const = default;

  /// True when every pole is labelled, none is contradictory and every sample has one
  /// inner and one outer pole.
  bool is_clean() const {
    return unlabelled == 0 && contradictory == 0 && inconsistent_samples == 0 &&
           samples_without_inner == 0;
  }
};

/// \throws InvalidInput if a threshold is NaN or outside [−1, 1] (label_poles checks this
/// first; callers that label later check it before their expensive stages).
void check_labeling_parameters(const LabelingParameters& parameters);

/// Labels `poles` in place (poles.label) and returns the counts.
/// \throws InvalidInput if a threshold is NaN or outside [−1, 1].
LabelingStats label_poles(PoleSet& poles, std::span<const Point3> samples,
                          const LabelingParameters& parameters = {});

}  // namespace rstruct::poles
