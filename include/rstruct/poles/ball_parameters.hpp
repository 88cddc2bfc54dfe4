#pragma once
/// \file
/// The scale factors of the paper's ball sets and their guards.
///
/// - ρ (rho): surface ball B(s, ρ·D̂(s)). Lemma 5.6 proves the union of surface balls
///   homotopy-equivalent to F for ρ ∈ [0.24, 0.56] (equation (1)).
/// - ρ̃ (rho_tilde): shrunk ball B(s, ρ̃·D̂(s)) used for pruning by set cover. Theorem 6.1
///   holds for ρ̃ ≤ 0.03 (and ρ̃ < ρ).
/// - ε (eps): enlargement of the inner polar balls for the medial-axis covering (§5.1,
///   DMAT'_in), absolute, or relative to the bounding-box diagonal of the samples.
///
/// Values outside the guaranteed ranges are allowed (levels of detail need them) and yield
/// warnings; values that are meaningless (NaN, infinite, negative, ρ = 0) are errors.

#include <string>
#include <vector>

namespace rstruct::poles {

/// Guaranteed range of ρ, paper equation (1).
inline constexpr double kRhoMin = 0.24;
inline constexpr double kRhoMax = 0.56;
/// Largest shrink factor ρ̃ covered by Theorem 6.1.
inline constexpr double kRhoTildeMax = 0.03;

struct BallParameters {
  double rho = 0.3;          ///< surface-ball factor ρ
  double rho_tilde = 0.03;   ///< shrunk-ball factor ρ̃
  double eps = 0.0;          ///< polar-ball enlargement ε (absolute, or relative: see below)
  bool eps_relative = false; ///< if true, ε is multiplied by the samples' bounding-box diagonal
};

/// Outcome of the guard: the warnings to print on stderr and record in the report. Every
/// warning means that the topology guarantee (Lemma 5.6 / Theorem 6.1) no longer holds.
struct ParameterCheck {
  std::vector<std::string> warnings;
  bool topology_guarantee_holds() const { return warnings.empty(); }
};

/// Checks `parameters`.
/// \throws InvalidInput if ρ, ρ̃ or ε is NaN or infinite, ρ ≤ 0, ρ̃ < 0 or ε < 0.
/// Warns (does not throw) when ρ ∉ [0.24, 0.56], ρ̃ > 0.03 or ρ̃ ≥ ρ.
ParameterCheck check_ball_parameters(const BallParameters& parameters);

/// The absolute ε: `parameters.eps`, times `bbox_diagonal` when eps_relative.
/// \throws InvalidInput if bbox_diagonal is negative or not finite.
double absolute_eps(const BallParameters& parameters, double bbox_diagonal);

}  // namespace rstruct::poles
