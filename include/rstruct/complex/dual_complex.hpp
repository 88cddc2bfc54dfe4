#pragma once
/// \file
/// The dual complex K of a union of balls (Edelsbrunner, "The union of balls and its dual
/// shape", DCG 13 (1995)): the weighted α-shape at α = 0 (DESIGN.md §4; issue 7).
///
/// Input: weighted points (ball (c, r) ↦ (c, r²)) and the finite cells of their regular
/// triangulation R. A simplex σ of R belongs to K iff the intersection V_σ of the power
/// cells of its vertices meets the union of the balls, i.e. iff min over V_σ of the common
/// power π_σ is ≤ 0. Computed top-down: a tetrahedron's dual is its orthocentre, so it is
/// in K iff its orthosphere has π ≤ 0; a lower simplex σ whose smallest orthosphere centre
/// z_σ lies in V_σ (σ *unattached*) is in K iff π_σ(z_σ) ≤ 0; if z_σ is outside V_σ
/// (*attached*: some vertex p with σ ∪ {p} in R has π_p(z_σ) < π_σ(z_σ)) the minimum lies
/// on the boundary of V_σ, whose pieces are the duals of σ's cofaces, so σ ∈ K iff one of
/// its cofaces is. Every sign comes from the exact predicates of
/// orthosphere_predicates.hpp; no tolerance, no perturbation (ties are decided as what they
/// are: touching balls are connected).
///
/// Facets of R are classified relative to K as exterior (not in K), singular (in K, no
/// incident tetrahedron in K), regular (one incident tetrahedron in K) or interior (two).

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "rstruct/complex/simplicial_complex.hpp"
#include "rstruct/geometry/vec3.hpp"

namespace rstruct::triangulation {
class RegularTriangulation3;
}

namespace rstruct::complex {

enum class FacetClass : std::uint8_t { exterior, singular, regular, interior };

const char* to_string(FacetClass c);

/// K together with the regular triangulation it was classified on.
struct DualComplex {
  /// Every finite simplex of R; vertex ids are indices of the input points.
  SimplicialComplex triangulation;
  /// in_k[d][i]: simplex i of dimension d of `triangulation` belongs to K.
  std::array<std::vector<bool>, 4> in_k;
  /// Class of every triangle of `triangulation`.
  std::vector<FacetClass> facet_class;

  /// K itself.
  SimplicialComplex complex() const { return triangulation.subcomplex(in_k); }
  /// Number of simplices of K by dimension.
  std::array<std::size_t, 4> counts() const;
  /// Number of facets per class, indexed by FacetClass.
  std::array<std::size_t, 4> facet_class_counts() const;
};

/// Classifies every simplex of the regular triangulation given by its finite cells.
/// \pre `cells` are the finite cells of the regular triangulation of `points` (vertex ids
///   index `points`; hidden points appear in no cell).
/// \throws InvalidInput if a cell names a point out of range or repeats a vertex, or if a
///   simplex is affinely degenerate (which a regular triangulation never has).
DualComplex dual_complex(std::span<const WeightedPoint> points,
                         std::span<const Tetrahedron> cells);

/// K of the weighted points of a regular triangulation (its finite cells and its input
/// points with their weights; hidden and merged points are in no cell).
DualComplex dual_complex(const triangulation::RegularTriangulation3& triangulation);

}  // namespace rstruct::complex
