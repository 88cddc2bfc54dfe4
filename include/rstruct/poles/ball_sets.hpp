#pragma once
/// \file
/// The ball sets of the pipeline (paper §3, §5, §6; DESIGN.md §2):
///  - surface balls B(s, ρ·D̂(s)) (§5.2, Lemma 5.6),
///  - shrunk balls B(s, ρ̃·D̂(s)) (§6, Theorem 6.1), the columns of the pruning set cover,
///  - enlarged inner polar balls B(p, R_p + ε) = DMAT'_in (§5.1), the columns of the
///    medial-axis set cover.
/// Radii are doubles: fl(ρ·D̂(s)) and fl(R_p + ε); every later decision about a ball is exact
/// for that double radius.

#include <cstdint>
#include <span>
#include <vector>

#include "rstruct/geometry/vec3.hpp"
#include "rstruct/poles/pole_set.hpp"

namespace rstruct::poles {

/// Balls B(samples[i], factor·dhat[i]), one per sample, in sample order.
/// \throws InvalidInput if the sizes differ, factor is negative or not finite, or some
/// dhat is negative or not finite.
std::vector<Ball> scaled_sample_balls(std::span<const Point3> samples,
                                      std::span<const double> dhat, double factor);

/// The inner polar balls with radius R_p + eps, and which pole each one is.
struct PolarBalls {
  std::vector<Ball> balls;
  std::vector<std::uint32_t> pole;  ///< index into the PoleSet
};

/// DMAT'_in: every pole labelled inner, in pole order, radius enlarged by `eps` (≥ 0).
/// \throws InvalidInput if eps is negative or not finite.
PolarBalls inner_polar_balls(const PoleSet& poles, double eps);

}  // namespace rstruct::poles
