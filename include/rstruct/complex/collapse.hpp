#pragma once
/// \file
/// Free-face collapse (DESIGN.md §5; issue 7 "Seed polytope"): a simplex σ is *free* if it
/// is a proper face of exactly one simplex τ of the complex; then τ is maximal and
/// dim τ = dim σ + 1, and removing σ and τ together (an elementary collapse, Whitehead)
/// keeps the homotopy type. Collapsing until no free face remains turns the dual complex
/// K of the kept surface balls into the seed polytope.
///
/// Order (deterministic): among the free faces, those of the highest dimension are
/// collapsed first (tetrahedra go before dangling triangles, which go before dangling
/// edges); within one dimension, first in, first out, where the initial queue lists the
/// simplices in index order and later candidates are appended as collapses create them.
/// Different orders may end in different complexes (e.g. a ball may get stuck on a
/// dunce-hat-like complex); all of them have the homotopy type of the input.

#include <array>
#include <cstddef>

#include "rstruct/complex/simplicial_complex.hpp"

namespace rstruct::complex {

struct CollapseResult {
  SimplicialComplex complex;                ///< what remains: no free face left
  std::array<std::size_t, 4> removed{};     ///< simplices removed, by dimension
  std::size_t collapses = 0;                ///< elementary collapses performed
};

/// Collapses free faces of `complex` until none remain. Linear time in practice (each
/// simplex is examined a bounded number of times per change of its coface count).
CollapseResult collapse_free_faces(const SimplicialComplex& complex);

}  // namespace rstruct::complex
