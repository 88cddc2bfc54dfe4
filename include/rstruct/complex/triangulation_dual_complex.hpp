#pragma once
/// \file
/// The dual complex K of a union of balls (Edelsbrunner 1995; DESIGN.md §4), classified
/// directly on the cells, facets and edges of the balls' RegularTriangulation3, in
/// parallel. Same definition and the same exact predicates as dual_complex.hpp (which
/// first copies the triangulation into a SimplicialComplex and indexes its cofaces), but
/// the cofaces come from the triangulation itself: a facet's cofaces are its two cells, an
/// edge's are the facets through it in the cells of its lower vertex's star (one pass over
/// that star classifies all the vertex's edges to higher vertices), a vertex's are the
/// edges to its neighbours (VertexStars). Only K is built as a SimplicialComplex, which
/// for pruned ball sets is a small part of the triangulation. The decisions are those of
/// orthosphere_is_unattached_in_union, so the result equals dual_complex()'s exactly and
/// does not depend on the number of threads.
///
/// Top-down, as in dual_complex.hpp: a finite cell is in K iff its orthosphere has power
/// ≤ 0; a lower simplex σ is in K iff one of its cofaces is, or σ is unattached (no vertex
/// p of a coface has π_p(z_σ) < π_σ(z_σ)) and π_σ(z_σ) ≤ 0. The four stages (cells,
/// facets, edges, vertices) each run over their simplices in parallel. A simplex with two
/// balls that are certainly disjoint (disjoint_balls.hpp) has π_σ(z_σ) > 0: the cell stage
/// records such pairs, and the facets and edges of a pair skip the predicates.

#include <array>
#include <cstddef>

#include "rstruct/complex/simplicial_complex.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"
#include "rstruct/triangulation/vertex_stars.hpp"

namespace rstruct::complex {

struct TriangulationDualComplex {
  /// K; vertex ids are the triangulation's vertex ids (indices of its input points).
  SimplicialComplex complex;
  /// Finite simplices of the triangulation by dimension (vertices, edges, facets, cells).
  std::array<std::size_t, 4> triangulation_counts{};
  /// Facets of the triangulation by class (exterior, singular, regular, interior), as in
  /// DualComplex::facet_class_counts().
  std::array<std::size_t, 4> facet_classes{};
};

/// K of the weighted points of `rt` (hidden and merged points are in no simplex).
/// If the neighbour lists of `stars` are deferred (VertexStars::Neighbors::deferred), the
/// edge pass, which reads every star, lists them and installs them in `stars`.
/// \pre `stars` was built from `rt`.
/// \throws InvalidInput if a simplex of `rt` is affinely degenerate (never, for a valid
///   regular triangulation); InternalError if the classified set is not closed under faces.
TriangulationDualComplex classify_dual_complex(const triangulation::RegularTriangulation3& rt,
                                               triangulation::VertexStars& stars,
                                               unsigned threads = 0);

}  // namespace rstruct::complex
