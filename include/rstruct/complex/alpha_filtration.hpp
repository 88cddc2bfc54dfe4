#pragma once
/// \file
/// The weighted α filtration of a set of balls (Edelsbrunner, "The union of balls and its
/// dual shape", DCG 13 (1995); issue 7's optional output): for every simplex σ of the
/// balls' regular triangulation R, the smallest α at which σ belongs to K_α, the dual
/// complex of the balls grown to weights w + α (radii √(r² + α)). K_0 is the dual complex
/// K of dual_complex.hpp.
///
/// Adding α to every weight moves no power cell, and moves every power π_i(x) = |x − c_i|² −
/// w_i by −α, so σ ∈ K_α iff the minimum of π_σ over its dual face V_σ is ≤ α:
///   α(σ) = min over V_σ of π_σ.
/// Computed top-down as K is: a cell's α is π of its orthosphere; a lower simplex σ that is
/// unattached (z_σ ∈ V_σ, no coface vertex p with π_p(z_σ) < π_σ(z_σ)) has α(σ) = π_σ(z_σ),
/// an attached one the minimum over its cofacets (the boundary of V_σ is made of their dual
/// faces). Attachment does not depend on α and is decided by the exact predicates of
/// orthosphere_predicates.hpp. The values are floating-point constructions
/// (orthosphere_power_value: the exact sign, within a relative 2⁻²⁸ of the exact value),
/// and every simplex takes the minimum of its own value and its cofacets', which equals its
/// own value exactly when it is unattached but keeps faces at or below their cofaces even
/// where two values differ by less than their rounding. Hence:
///  - σ ∈ K iff α(σ) ≤ 0, exactly (each value has its exact sign; see the .cpp);
///  - for any t, {σ : α(σ) ≤ t} is K_t except for simplices whose exact α lies within
///    the values' rounding of t;
///  - α(face) ≤ α(coface): sorting by (α, dimension) gives a filtration.

#include <array>
#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "rstruct/complex/simplicial_complex.hpp"
#include "rstruct/geometry/vec3.hpp"

namespace rstruct::triangulation {
class RegularTriangulation3;
}

namespace rstruct::complex {

struct AlphaFiltration {
  /// Every finite simplex of R; vertex ids are indices of the input points.
  SimplicialComplex triangulation;
  /// alpha[d][i]: α of simplex i of dimension d of `triangulation`.
  std::array<std::vector<double>, 4> alpha;
  /// attached[d][i], d ≤ 2: the simplex is attached (its α comes from a cofacet).
  std::array<std::vector<bool>, 3> attached;

  /// Flags of the simplices with α ≤ t, one vector per dimension (K for t = 0).
  std::array<std::vector<bool>, 4> sublevel(double t) const;
  /// Every simplex as (dimension, index), sorted by α, then dimension, then index: each
  /// face comes before its cofaces.
  std::vector<std::pair<int, SimplexIndex>> order() const;
};

/// The α filtration of weighted points given the finite cells of their regular
/// triangulation (as dual_complex(points, cells)), each dimension's simplices on `threads`
/// threads (0: all cores; the result does not depend on the count).
/// \pre `cells` are the finite cells of the regular triangulation of `points`.
/// \throws InvalidInput if a cell names a point out of range or repeats a vertex, or if a
///   simplex is affinely degenerate (which a regular triangulation never has).
AlphaFiltration alpha_filtration(std::span<const WeightedPoint> points,
                                 std::span<const Tetrahedron> cells, unsigned threads = 0);

/// The α filtration of the weighted points of a regular triangulation.
AlphaFiltration alpha_filtration(const triangulation::RegularTriangulation3& triangulation,
                                 unsigned threads = 0);

}  // namespace rstruct::complex
