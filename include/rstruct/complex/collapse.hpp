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
/// edges). Within one dimension the candidates wait in a queue seeded with the simplices
/// in index order and fed as collapses expose new ones; CollapseOrder says which end is
/// served. Different orders may end in different complexes; all of them have the homotopy
/// type of the input, none is guaranteed to be minimal (a collapsible complex may get
/// stuck on a dunce-hat-like 2-complex). Measured (tests/complex, /tmp probes in the note):
///  - Kuhn-subdivided cubes n³ (balls) under random vertex labels: breadth-first always
///    reached a point (n = 3: 300/300, n = 5: 100/100, n = 8: 20/20); depth-first got stuck
///    on 2-complexes (n = 3: 43/300, n = 5: 94/100).
///  - dual complexes of torus surface balls (thick shells, 120 × 48 samples, ρ ∈ {0.4,
///    0.56}, six samplings): depth-first always ended on a closed torus (12/12);
///    breadth-first left non-manifold walls where fronts from the inner and outer boundary
///    meet (0/12 manifold).
/// So: depth_first for the seed polytope (dual complex of surface balls), breadth_first
/// for solid regions.

#include <array>
#include <cstddef>

#include "rstruct/complex/simplicial_complex.hpp"

namespace rstruct::complex {

enum class CollapseOrder {
  breadth_first,  ///< oldest candidate first: fronts advance from every free face at once
  depth_first     ///< newest candidate first: keep eating into the region just exposed
};

struct CollapseResult {
  SimplicialComplex complex;                ///< what remains: no free face left
  std::array<std::size_t, 4> removed{};     ///< simplices removed, by dimension
  std::size_t collapses = 0;                ///< elementary collapses performed
};

/// Collapses free faces of `complex` until none remain. Linear time in practice (each
/// simplex is examined a bounded number of times per change of its coface count).
CollapseResult collapse_free_faces(const SimplicialComplex& complex,
                                   CollapseOrder order = CollapseOrder::breadth_first);

}  // namespace rstruct::complex
