#pragma once
/// \file
/// Combinatorial 2-manifold tests and orientation (DESIGN.md §5, §7): the seed polytope
/// must be a closed triangulated 2-manifold, and output meshes are written with
/// consistently oriented triangles when the surface is orientable.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "rstruct/complex/simplicial_complex.hpp"

namespace rstruct::complex {

/// Outcome of the closed-2-manifold test, with counts of what breaks it.
struct ManifoldCheck {
  bool is_closed_2_manifold = false;
  std::size_t tetrahedra = 0;               ///< any tetrahedron breaks it
  std::size_t edges_not_in_two_triangles = 0;
  std::size_t vertices_with_bad_link = 0;   ///< link not a single cycle (includes isolated)
  std::string first_problem;                ///< human-readable first failure, empty if none
};

/// Closed 2-manifold test: non-empty, no tetrahedra, every edge in exactly two triangles
/// and the link of every vertex a single cycle (DESIGN.md §7).
ManifoldCheck check_closed_2_manifold(const SimplicialComplex& complex);

/// Shorthand for check_closed_2_manifold(complex).is_closed_2_manifold.
bool is_closed_2_manifold(const SimplicialComplex& complex);

/// Consistent orientation of the triangles of a surface (possibly with boundary):
/// triangles sharing an edge induce opposite directions on it. Triangles are returned in
/// the complex's triangle order, each either (a, b, c) or (a, c, b) for its sorted
/// vertices; in every connected component (through shared edges) the lowest-index triangle
/// keeps its sorted order. Returns nullopt if the surface is not orientable.
/// \throws InvalidInput if some edge lies in more than two triangles (names the edge).
std::optional<std::vector<Triangle>> orient_triangles(const SimplicialComplex& complex);

}  // namespace rstruct::complex
